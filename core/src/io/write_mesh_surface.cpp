// A 2D mesh through the surface writers (surface_io.hpp), in the plane z = 0: the formats
// every 3D program opens, for a mesh whose segments and regions they would not keep anyway.
#include "io/planar_mesh_check.hpp"
#include "meshstep/io/mesh_formats.hpp"

namespace meshstep::io {
namespace {

void write_as(const std::string& path, const TriMesh& mesh, SurfaceFormat format) {
  detail::check_planar_mesh(path, mesh);
  write_surface(path, planar_surface(mesh), format);
}

}  // namespace

Surface planar_surface(const TriMesh& mesh) {
  Surface s;
  s.vertices.reserve(mesh.points.size());
  for (const Point& p : mesh.points) s.vertices.push_back({p.x, p.y, 0.0});
  s.triangles = mesh.triangles;  // counterclockwise in the plane: outward is +z
  return s;
}

void write_mesh_off(const std::string& path, const TriMesh& mesh) { write_as(path, mesh, SurfaceFormat::off); }
void write_mesh_obj(const std::string& path, const TriMesh& mesh) { write_as(path, mesh, SurfaceFormat::obj); }
void write_mesh_ply(const std::string& path, const TriMesh& mesh) { write_as(path, mesh, SurfaceFormat::ply_binary); }
void write_mesh_stl(const std::string& path, const TriMesh& mesh) { write_as(path, mesh, SurfaceFormat::stl_binary); }

}  // namespace meshstep::io
