// Index handles shared by the mesh data structures.
#pragma once

#include <cstdint>

namespace meshstep {

using VertexId = std::uint32_t;  // index into the triangulation's point array
using FaceId = std::uint32_t;
using HalfEdge = std::uint32_t;  // a directed edge of one face; its face lies on its left

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;
// The vertex "at infinity": faces incident to it (ghost faces) close the triangulation
// of a point set into a sphere, so insertion outside the convex hull needs no special case.
inline constexpr VertexId kInfiniteVertex = 0xFFFFFFFEu;

}  // namespace meshstep
