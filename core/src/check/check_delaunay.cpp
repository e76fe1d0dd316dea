// Stage 5: constrained Delaunay, checked locally. In a valid triangulation, every
// unconstrained interior edge being locally Delaunay implies the whole mesh is constrained
// Delaunay, so one exact incircle per such edge suffices.
#include <algorithm>

#include "check/stages.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep::check_detail {

void check_delaunay(MeshFacts& facts) {
  const auto& mesh = facts.mesh;
  const auto& p = mesh.points;
  const EdgeTable& table = *facts.edges;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!facts.good(t)) continue;
    const auto& tri = mesh.triangles[t];
    for (std::uint32_t i = 0; i < 3; ++i) {
      const auto edge = static_cast<std::uint32_t>(3 * t + i);
      const std::uint32_t twin = table.twin(edge);
      // Each interior edge once, from its lower id; boundary and broken edges have no
      // opposite triangle to test against.
      if (twin == EdgeTable::kBoundary || twin == EdgeTable::kNonManifold || twin < edge) continue;
      const std::size_t u = twin / 3;
      if (!facts.good(u)) continue;
      const std::uint32_t a = tri[(i + 1) % 3], b = tri[(i + 2) % 3];
      if (facts.listed_edge[edge]) continue;
      const std::uint32_t d = mesh.triangles[u][twin % 3];
      // (a, b, tri[i]) is a rotation of the ccw triangle, as incircle requires.
      if (incircle(p[a], p[b], p[tri[i]], p[d]) <= 0.0) continue;
      facts.log.add([&] {
        return "edge (" + facts.vertex(std::min(a, b)) + " " + facts.vertex(std::max(a, b)) +
               ") between " + facts.triangle(t) + " and triangle " + number(u, mesh.first_index) +
               " is not Delaunay: vertex " + facts.vertex(d) +
               " lies strictly inside the circumcircle of triangle " +
               number(t, mesh.first_index) + ", and the edge is not a segment";
      });
    }
  }
}

}  // namespace meshstep::check_detail
