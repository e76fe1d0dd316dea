#include "io/planar_mesh_check.hpp"

#include <cmath>

#include "meshstep/error.hpp"
#include "meshstep/io/shortest_text.hpp"

namespace meshstep::io::detail {
namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& message) {
  throw InputError(path, 0, "cannot write this mesh: " + message);
}

}  // namespace

void check_planar_mesh(const std::string& path, const TriMesh& mesh) {
  const std::size_t n = mesh.points.size();
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(mesh.points[i].x) || !std::isfinite(mesh.points[i].y))
      refuse(path, "vertex " + std::to_string(i) + " has a coordinate that is not finite (" +
                       shortest_text(mesh.points[i].x) + ", " + shortest_text(mesh.points[i].y) + ")");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const std::uint32_t v : mesh.triangles[t])
      if (v >= n)
        refuse(path, "triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) + ", but there are only " +
                         std::to_string(n) + " vertices");
  for (std::size_t s = 0; s < mesh.segments.size(); ++s)
    if (mesh.segments[s].a >= n || mesh.segments[s].b >= n)
      refuse(path, "segment " + std::to_string(s) + " uses a vertex past the last (" + std::to_string(n) + ")");
  if (!mesh.vertex_markers.empty() && mesh.vertex_markers.size() != n)
    refuse(path, std::to_string(mesh.vertex_markers.size()) + " vertex markers for " + std::to_string(n) + " vertices");
  if (mesh.triangle_attributes.size() != mesh.triangles.size() * mesh.attributes_per_triangle)
    refuse(path, std::to_string(mesh.triangle_attributes.size()) + " triangle attributes for " +
                     std::to_string(mesh.triangles.size()) + " triangles");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (!std::isfinite(region_of(mesh, t)))
      refuse(path, "triangle " + std::to_string(t) + " has a region attribute that is not finite");
}

}  // namespace meshstep::io::detail
