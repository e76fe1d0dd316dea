// Which surface format a path names (io/surface_io.hpp).
#include <cctype>

#include "meshstep/io/surface_io.hpp"

namespace meshstep::io {

std::optional<SurfaceFormat> surface_format_for(const std::string& path, bool ascii) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "off") return SurfaceFormat::off;
  if (ext == "obj") return SurfaceFormat::obj;
  if (ext == "ply") return ascii ? SurfaceFormat::ply_ascii : SurfaceFormat::ply_binary;
  if (ext == "stl") return ascii ? SurfaceFormat::stl_ascii : SurfaceFormat::stl_binary;
  return std::nullopt;
}

}  // namespace meshstep::io
