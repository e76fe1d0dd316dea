// read_surface: the reader for the path's extension (io/surface_io.hpp), and the helpers
// the readers share.
#include "io/surface_readers.hpp"
#include "meshstep/error.hpp"

namespace meshstep::io {
namespace detail {

void add_fan(std::vector<std::array<std::uint32_t, 3>>& triangles,
             const std::vector<std::uint32_t>& corners) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
}

void fail_at_byte(const std::string& path, std::uint64_t offset, const std::string& message) {
  throw InputError(path, 0, "byte offset " + std::to_string(offset) + ": " + message);
}

}  // namespace detail

Surface read_surface(const std::string& path) {
  const std::optional<SurfaceFormat> format = surface_format_for(path);
  if (!format) {
    throw InputError(path, 0, "unknown surface file type: expected .off, .obj, .ply or .stl");
  }
  switch (*format) {
    case SurfaceFormat::off: return detail::read_off(path);
    case SurfaceFormat::obj: return detail::read_obj(path);
    case SurfaceFormat::ply_ascii:
    case SurfaceFormat::ply_binary: return detail::read_ply(path);
    case SurfaceFormat::stl_ascii:
    case SurfaceFormat::stl_binary: return detail::read_stl(path);
  }
  throw InputError(path, 0, "unknown surface format");  // not reached: every case returns
}

}  // namespace meshstep::io
