#include "check/segment_crossing.hpp"

#include <algorithm>

#include "meshstep/geometry/predicates.hpp"

namespace meshstep::check_detail {
namespace {

// Separating-axis test of segment pq against the ccw triangle abc. The triangle's edges
// separate exactly (both ends on the closed outer side); the segment's line separates
// when no corner lies beyond the tolerance on one of its sides, so a sliver next to a
// chain bent by a rounded crossing point does not count as being cut.
bool passes_through(const Point& p, const Point& q, const Point& a, const Point& b,
                    const Point& c, double max_cross) {
  const Point* corners[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const Point &u = *corners[i], &v = *corners[(i + 1) % 3];
    if (orient2d(u, v, p) <= 0.0 && orient2d(u, v, q) <= 0.0) return false;
  }
  const double dx = q.x - p.x, dy = q.y - p.y;
  double lo = 0.0, hi = 0.0;
  for (const Point* t : corners) {
    const double cross = dx * (t->y - p.y) - dy * (t->x - p.x);  // |pq| x signed distance
    lo = std::min(lo, cross);
    hi = std::max(hi, cross);
  }
  return hi > max_cross && lo < -max_cross;
}

}  // namespace

std::optional<std::uint32_t> crossed_triangle(MeshFacts& facts, const Point& p, const Point& q) {
  const auto& mesh = facts.mesh;
  BBox segment_box;
  segment_box.add(p);
  segment_box.add(q);
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double max_cross = 1e-9 * (dx * dx + dy * dy);
  std::optional<std::uint32_t> found;
  // Boxes wholly on one side of the segment's line hold no triangle it crosses.
  auto skip = [&](const BBox& node) {
    return found || !boxes_overlap(node, segment_box) || box_right_of(node, p, q) ||
           box_right_of(node, q, p);
  };
  facts.triangle_tree().query(skip, [&](std::uint32_t t) {
    if (found) return;
    const auto& tri = mesh.triangles[t];
    if (passes_through(p, q, mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]],
                       max_cross))
      found = t;
  });
  return found;
}

}  // namespace meshstep::check_detail
