// The cheap checks every command makes before it writes a mesh (the full checker is
// check/; the fuzzers run it). A failure is a bug in meshstep, never the input's fault:
// std::logic_error, which the commands report as an internal error, writing nothing.
//
// Why these suffice for the triangulation of the whole point set (before carving): the
// mesh closed by the vertex at infinity is a sphere, so if every vertex is the corner of a
// face and the faces number 2V - 2 (Euler), the finite faces form a disk. If moreover every
// finite face is counterclockwise and the disk's boundary (the hull) turns left once round,
// each point of the hull is covered by exactly as many faces as the boundary winds round
// it, once: no fold, no overlap, no vertex lost inside a triangle.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshstep/geometry/predicates.hpp"
#include "meshstep/mesh/concept.hpp"

namespace meshstep {

namespace detail {

// Which half of the turn the direction b - a points into: [0, pi) is 0, [pi, 2 pi) is 1.
// Exact: the sign of a difference of doubles is the sign of the exact difference.
inline int direction_half(const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return dy < 0.0 || (dy == 0.0 && dx < 0.0) ? 1 : 0;
}

// For collinear a, b, c: whether b - a and c - b point the same way (no turning back).
inline bool same_direction(const Point& a, const Point& b, const Point& c) {
  const auto sign = [](double d) { return (d > 0.0) - (d < 0.0); };
  return sign(b.x - a.x) == sign(c.x - b.x) && sign(b.y - a.y) == sign(c.y - b.y);
}

[[noreturn]] inline void broken(const std::string& what) {
  throw std::logic_error("the triangulation made is broken: " + what);
}

}  // namespace detail

// Counts, corners, orientation and hull of a triangulation closed by the vertex at infinity
// (delaunay/triangulation.hpp), before anything is carved from it. One pass over the faces
// and one round of the hull: about 2% of a triangulation's instructions (the output then
// checks nothing again unless an algorithm changed the mesh).
template <class Tri>
void check_whole_triangulation(const Tri& tri) {
  const auto& m = tri.mesh();
  const std::size_t vertex_ids = tri.points().size();
  const std::size_t expected = vertex_ids - tri.duplicate_count() - tri.removed_vertices().size();
  // One byte a vertex, the vertex at infinity in the last: stores without a branch.
  std::vector<std::uint8_t> corner(vertex_ids + 1, 0);
  const auto slot = [&](VertexId v) { return v == kInfiniteVertex ? vertex_ids : v; };
  std::size_t faces = 0;
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f)) continue;
    ++faces;
    const HalfEdge h = m.half_edge(f);
    const VertexId a = m.origin(h), b = m.dest(h), c = m.apex(h);
    corner[slot(a)] = corner[slot(b)] = corner[slot(c)] = 1;
    if (a != kInfiniteVertex && b != kInfiniteVertex && c != kInfiniteVertex &&
        !(orient2d(tri.point(a), tri.point(b), tri.point(c)) > 0.0))
      detail::broken("face " + std::to_string(f) + " is not counterclockwise");
  }
  const auto corners = static_cast<std::size_t>(std::count(corner.begin(), corner.end() - 1, 1));
  if (corners != expected)
    detail::broken(std::to_string(expected - corners) + " of its " + std::to_string(expected) +
                   " vertices are the corner of no face");
  if (faces != 2 * corners - 2)
    detail::broken(std::to_string(faces) + " faces for " + std::to_string(corners) +
                   " vertices, where a sphere has " + std::to_string(2 * corners - 2));

  // The hull, in the order the ghost faces go round the vertex at infinity: ghost face
  // (inf, d, a) stands outside the hull edge a -> d, and the next ghost face is (inf, a, ...),
  // so the round walks the hull clockwise: d, a, ... It must turn right (or go straight on)
  // at every vertex, and wind once.
  const HalfEdge start = m.vertex_half_edge(kInfiniteVertex);
  std::size_t hull = 0, wraps = 0;
  for (HalfEdge h = start;;) {
    const HalfEdge next = m.twin(m.prev(h));
    const Point& a = tri.point(m.dest(h));
    const Point& b = tri.point(m.apex(h));
    const Point& c = tri.point(m.apex(next));
    const double turn = orient2d(a, b, c);
    if (!(turn < 0.0 || (turn == 0.0 && detail::same_direction(a, b, c))))
      detail::broken("its hull turns the wrong way at a vertex");
    wraps += detail::direction_half(a, b) == 0 && detail::direction_half(b, c) == 1;
    ++hull;
    h = next;
    if (h == start) break;
    if (hull > faces) detail::broken("the faces round the vertex at infinity do not close");
  }
  if (wraps != 1) detail::broken("its hull winds round " + std::to_string(wraps) + " times");
}

}  // namespace meshstep
