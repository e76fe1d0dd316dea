// What the single-file mesh writers (mesh_formats.hpp) check before touching their target:
// what no reader would take back, refused as InputError(path, 0, "cannot write this mesh: ...").
#pragma once

#include <string>

#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep::io::detail {

// Finite coordinates and attributes; triangle and segment indices within the vertices;
// per-vertex and per-triangle arrays either empty or of the right length.
void check_planar_mesh(const std::string& path, const TriMesh& mesh);

// The region attribute of triangle t (0 when the mesh has none).
inline double region_of(const TriMesh& mesh, std::size_t t) {
  return mesh.attributes_per_triangle == 0 ? 0.0 : mesh.triangle_attributes[t * mesh.attributes_per_triangle];
}

}  // namespace meshstep::io::detail
