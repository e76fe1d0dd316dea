// The undirected edges of a triangle list, each with the triangle sides that use it: what
// both compute_neighbors and write_edge need. Linear time (bucketed by the smaller vertex),
// so that a mesh of millions of triangles is handled in a fraction of a second.
#pragma once

#include <cstdint>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep::io::detail {

// A triangle side: 3 * triangle + i, the side opposite triangles[triangle][i].
struct EdgeGroups {
  std::vector<std::uint32_t> start;  // group g is sides[start[g], start[g + 1])
  std::vector<std::uint32_t> sides;  // within a group, in increasing order
  std::size_t size() const { return start.empty() ? 0 : start.size() - 1; }
};

// Endpoints of a side, in the triangle's (counterclockwise) order.
inline std::uint32_t side_from(const TriMesh& m, std::uint32_t side) {
  return m.triangles[side / 3][(side % 3 + 1) % 3];
}
inline std::uint32_t side_to(const TriMesh& m, std::uint32_t side) {
  return m.triangles[side / 3][(side % 3 + 2) % 3];
}

// Throws std::length_error when the mesh has more than 2^32 / 3 triangles.
EdgeGroups group_edges(const TriMesh& mesh);

}  // namespace meshstep::io::detail
