// Triangle's formats: the first byte picks the reader (.node, .poly, or a mesh: .node
// then .ele, split at the first NUL byte), the rest is the file.
#include <cstring>

#include "fuzz_support.hpp"
#include "meshstep/io/triangle_io.hpp"

using namespace meshstep;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t which = data[0] % 3;
  ++data, --size;
  fuzz::refusals_allowed([&] {
    if (which == 0) {
      io::read_node(fuzz::write_input(data, size, ".node"));
    } else if (which == 1) {
      io::read_poly(fuzz::write_input(data, size, ".poly"));
    } else {
      const auto* nul = static_cast<const std::uint8_t*>(std::memchr(data, 0, size));
      const std::size_t node = nul ? static_cast<std::size_t>(nul - data) : size;
      const std::string prefix = fuzz::write_input(data, node, ".node");
      const std::string base = prefix.substr(0, prefix.size() - 5);
      const std::size_t rest = nul ? size - node - 1 : 0;
      fuzz::write_input(nul ? nul + 1 : data, rest, ".ele");
      io::read_mesh(base);
    }
  });
  return 0;
}
