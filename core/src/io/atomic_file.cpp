#include "meshstep/io/atomic_file.hpp"

#include "atomic_writer.hpp"

namespace meshstep::io {

void write_file_atomically(const std::string& path, std::string_view bytes) {
  detail::AtomicWriter out(path);
  out.text(bytes);
  out.commit();
}

}  // namespace meshstep::io
