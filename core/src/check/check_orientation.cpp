// Stage 2: triangles must be strictly counterclockwise, decided by the exact orient2d.
#include "check/stages.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep::check_detail {

void check_orientation(MeshFacts& facts) {
  const auto& mesh = facts.mesh;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!facts.usable(t)) continue;
    const auto& tri = mesh.triangles[t];
    // Non-finite corners were reported with the vertex; the predicate means nothing there.
    if (!facts.finite_point[tri[0]] || !facts.finite_point[tri[1]] || !facts.finite_point[tri[2]])
      continue;
    const double o = orient2d(mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]);
    if (o > 0.0) {
      facts.tri_state[t] = TriState::kGood;
    } else if (o < 0.0) {
      facts.log.add([&] { return facts.triangle(t) + " is clockwise"; });
    } else {
      facts.log.add([&] {
        return facts.triangle(t) + " is degenerate: its vertices are collinear (zero area)";
      });
    }
  }
}

}  // namespace meshstep::check_detail
