#include "terrain_output.hpp"

#include "meshstep/io/triangle_io.hpp"
#include "meshstep/terrain/tin_surface.hpp"

namespace meshstep::app {

void write_terrain(const std::string& path, const std::optional<io::SurfaceFormat>& format,
                   const terrain::HeightGrid& grid, const terrain::Tin& tin, double base) {
  if (format) {
    io::Surface surface = terrain::to_surface(grid, tin);
    if (base > 0.0) terrain::add_solid_base(surface, grid, tin, base);
    io::write_surface(path, surface, *format);
    return;
  }
  TriMesh mesh;
  mesh.attributes_per_vertex = 1;
  for (std::uint32_t v = 0; v < tin.samples.size(); ++v) {
    const auto p = terrain::vertex_position(grid, tin, v);
    mesh.points.push_back({p[0], p[1]});
    mesh.vertex_attributes.push_back(p[2]);
  }
  mesh.triangles = tin.triangles;
  mesh.input_vertex_count = mesh.points.size();
  io::write_mesh(path.substr(0, path.rfind('.')), mesh);
}

}  // namespace meshstep::app
