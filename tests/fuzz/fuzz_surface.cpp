// 3D surfaces (.off, .obj, .ply, .stl): the first byte picks the reader. What reads must
// report without throwing, write, and read back the same.
#include <filesystem>

#include "fuzz_support.hpp"
#include "meshstep/io/surface_io.hpp"

using namespace meshstep;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[] = {".off", ".obj", ".ply", ".stl"};
  const std::string extension = kExtensions[data[0] % 4];
  fuzz::refusals_allowed([&] {
    const io::Surface s = io::read_surface(fuzz::write_input(data + 1, size - 1, extension));
    (void)io::describe(io::report_surface(s));
    const std::string again = (std::filesystem::temp_directory_path() / "fuzz_surface_again.ply").string();
    io::write_surface(again, s, io::SurfaceFormat::ply_binary);
    const io::Surface back = io::read_surface(again);
    if (back.vertices != s.vertices || back.triangles != s.triangles) fuzz::finding("a PLY round trip changed the surface");
  });
  return 0;
}
