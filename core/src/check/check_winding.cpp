// Stage 4a: around a vertex whose every edge is interior, the triangles must close up
// exactly once. Their corner angles then sum to 2*pi; a fold that wraps twice sums to 4*pi
// although every edge, taken alone, looks fine.
#include <cmath>
#include <numbers>

#include "check/stages.hpp"

namespace meshstep::check_detail {
namespace {

// Angle at corner p between the directions to q and r, in (0, pi): the triangles summed
// here are counterclockwise, as the exact orientation stage found them. The rounded cross
// product can come out negative for a sliver whose angle at p is nearly pi (a fuzzing
// finding: -pi instead of pi, so a fan round a vertex summed to 0), so its sign is not
// taken from the rounding.
double corner_angle(const Point& p, const Point& q, const Point& r) {
  const double ux = q.x - p.x, uy = q.y - p.y;
  const double vx = r.x - p.x, vy = r.y - p.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

}  // namespace

void check_winding(MeshFacts& facts) {
  const auto& mesh = facts.mesh;
  const EdgeTable& table = *facts.edges;
  // A vertex qualifies when it has triangles, all of them good, and every edge at it has
  // exactly one twin. Boundary vertices legitimately have angle sums below 2*pi.
  std::vector<std::uint8_t> interior(mesh.points.size(), 0);
  for (std::uint32_t v = 0; v < table.vertex_count(); ++v) interior[v] = !table.out(v).empty();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!facts.usable(t)) continue;
    const auto& tri = mesh.triangles[t];
    if (!facts.good(t)) {
      interior[tri[0]] = interior[tri[1]] = interior[tri[2]] = 0;
      continue;
    }
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t twin = table.twin(static_cast<std::uint32_t>(3 * t + i));
      if (twin == EdgeTable::kBoundary || twin == EdgeTable::kNonManifold)
        interior[tri[(i + 1) % 3]] = interior[tri[(i + 2) % 3]] = 0;
    }
  }

  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  for (std::uint32_t v = 0; v < table.vertex_count(); ++v) {
    if (!interior[v]) continue;
    double sum = 0.0;
    for (const auto& e : table.out(v)) {
      // Edge 3t+i starts at corner (i+1)%3, which is v; the corner after it is (i+2)%3.
      const auto& tri = mesh.triangles[e.edge / 3];
      const std::uint32_t i = e.edge % 3;
      sum += corner_angle(mesh.points[v], mesh.points[tri[(i + 2) % 3]], mesh.points[tri[i]]);
    }
    if (std::fabs(sum - kTwoPi) <= 1e-6) continue;
    facts.log.add([&] {
      return "the " + std::to_string(table.out(v).size()) + " triangles around vertex " +
             facts.vertex(v) + " wind " + std::to_string(std::lround(sum / kTwoPi)) +
             " times around it (angles sum to " + coordinate(sum) + " rad, not 2*pi): they overlap";
    });
  }
}

}  // namespace meshstep::check_detail
