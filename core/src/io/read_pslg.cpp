// Public entry points for reading a PSLG from a .node or .poly file.
#include "io/record_reader.hpp"
#include "io/sections.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/io/triangle_io.hpp"

namespace meshstep::io {

Pslg read_node(const std::string& path, std::vector<std::string>* warnings) {
  detail::RecordReader r(path);
  return detail::read_node_file(r, warnings);
}

Pslg read_poly(const std::string& path, std::vector<std::string>* warnings) {
  return detail::read_poly_file(path, nullptr, warnings);
}

Pslg read_pslg(const std::string& path, std::vector<std::string>* warnings) {
  const auto ends_with = [&](std::string_view ext) {
    return path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
  };
  if (ends_with(".node")) return read_node(path, warnings);
  if (ends_with(".poly")) return read_poly(path, warnings);
  // The polygon formats by the table (formats.hpp), in lower case as is_planar_input takes them.
  for (const FileFormat& f : file_formats())
    if (f.read_pslg && ends_with(f.extension)) return f.read_pslg(path, warnings);
  throw InputError(path, 0, "unknown file type: expected a .node or .poly file, or .geojson or .wkt polygons");
}

}  // namespace meshstep::io
