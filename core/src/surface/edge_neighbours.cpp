// opposite_corner_edges (edge_neighbours.hpp): sort the corner edges by their two vertices,
// and the (at most) two of each edge come out side by side.
#include "edge_neighbours.hpp"

#include <algorithm>
#include <cassert>

#include "meshstep/mesh/handles.hpp"
#include "meshstep/refine/lepp.hpp"

namespace meshstep::surface::detail {

std::vector<std::uint32_t> opposite_corner_edges(
    const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  struct Use {
    std::uint64_t edge;        // the two vertices, smaller first
    std::uint32_t corner_edge;
  };
  std::vector<Use> uses;
  uses.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t i = 0; i < 3; ++i)
      uses.push_back({edge_tie_key(triangles[t][i], triangles[t][(i + 1) % 3]), 3 * t + i});
  // By corner edge within an edge too, so the result never depends on the sort's whims.
  std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) {
    return a.edge != b.edge ? a.edge < b.edge : a.corner_edge < b.corner_edge;
  });
  std::vector<std::uint32_t> opposite(uses.size(), kNone);
  for (std::size_t i = 0; i + 1 < uses.size(); ++i) {
    if (uses[i].edge != uses[i + 1].edge) continue;
    assert(i + 2 >= uses.size() || uses[i + 2].edge != uses[i].edge);  // manifold
    opposite[uses[i].corner_edge] = uses[i + 1].corner_edge;
    opposite[uses[i + 1].corner_edge] = uses[i].corner_edge;
    ++i;
  }
  return opposite;
}

}  // namespace meshstep::surface::detail
