// Which triangle of a triangle list lies across each edge: the adjacency the surface loader
// needs to know which triangles to glue, worked out once from the list itself.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace meshstep::surface::detail {

// Triangles are numbered by their place in the list, and the edge of triangle t from
// corner i to corner i+1 (mod 3) is the "corner edge" 3t+i. The result holds, for every
// corner edge, the corner edge of the other triangle along the same two vertices, or kNone
// (meshstep/mesh/handles.hpp) when there is none. The list must be a manifold surface, as
// io::report_surface checks: no edge in more than two triangles, no repeated corner.
std::vector<std::uint32_t> opposite_corner_edges(
    const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace meshstep::surface::detail
