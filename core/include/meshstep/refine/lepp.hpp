// The longest-edge propagation path of a triangle (Rivara), on any TriangleMesh.
//
// Lepp(t): from t, cross its longest edge to the neighbour, and again, until the longest
// edge is a segment or on the boundary (one terminal triangle) or is also the longest edge
// of the neighbour across it (two terminal triangles); that last edge is the terminal edge.
// Between equal lengths the edge with the smallest pair of vertex ids is the longer, so a
// path depends only on the geometry and the vertex numbering, not on the data structure;
// with that order every step goes to a strictly longer edge, and the path ends.
#pragma once

#include <cstdint>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/mesh/concept.hpp"
#include "meshstep/refine/quality.hpp"

namespace meshstep {

// The order in which equal-length edges count as longer: smaller (min id, max id) first.
inline std::uint64_t edge_tie_key(VertexId a, VertexId b) {
  return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

// The longest edge of face f, as a half-edge of f.
template <TriangleMesh Mesh>
HalfEdge longest_edge(const Mesh& mesh, const std::vector<Point>& points, FaceId f) {
  HalfEdge best = kNone;
  double best_length = -1.0;
  std::uint64_t best_key = 0;
  const HalfEdge first = mesh.half_edge(f);
  for (const HalfEdge h : {first, mesh.next(first), mesh.prev(first)}) {
    const double l = quality::squared_distance(points[mesh.origin(h)], points[mesh.dest(h)]);
    const std::uint64_t k = edge_tie_key(mesh.origin(h), mesh.dest(h));
    if (l > best_length || (l == best_length && k < best_key)) {
      best = h;
      best_length = l;
      best_key = k;
    }
  }
  return best;
}

// The path of face f: its faces in order into `path` (the terminal triangles last), and the
// terminal edge as a half-edge of the first terminal triangle. `stops(h)` says that the
// path may not cross h (a segment; a boundary edge, whose twin is kNone, always stops it).
// There are two terminal triangles when the last face's twin across the terminal edge is
// in the path too, that is when path.size() >= 2 and the edge does not stop the path.
template <TriangleMesh Mesh, class Stops>
HalfEdge lepp(const Mesh& mesh, const std::vector<Point>& points, FaceId f, Stops stops,
              std::vector<FaceId>& path) {
  path.clear();
  HalfEdge e = longest_edge(mesh, points, f);
  for (;;) {
    path.push_back(mesh.face(e));
    const HalfEdge t = mesh.twin(e);
    if (t == kNone || stops(e)) return e;
    const HalfEdge next = longest_edge(mesh, points, mesh.face(t));
    if (next == t) {
      path.push_back(mesh.face(t));
      return e;
    }
    e = next;
  }
}

}  // namespace meshstep
