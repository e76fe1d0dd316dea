#include "meshstep/pslg/input_angles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "meshstep/geometry/predicates.hpp"

namespace meshstep {

std::optional<InputAngle> smallest_input_angle(const Pslg& in) {
  // Each segment once from each end: (vertex, direction, segment), sorted round each vertex.
  struct Spoke {
    std::uint32_t vertex, other, segment;
    double direction;  // atan2, in (-pi, pi]
  };
  std::vector<Spoke> spokes;
  spokes.reserve(2 * in.segments.size());
  for (std::uint32_t s = 0; s < in.segments.size(); ++s) {
    const Segment& seg = in.segments[s];
    if (seg.a >= in.points.size() || seg.b >= in.points.size()) continue;
    const Point &a = in.points[seg.a], &b = in.points[seg.b];
    if (a.x == b.x && a.y == b.y) continue;
    spokes.push_back({seg.a, seg.b, s, std::atan2(b.y - a.y, b.x - a.x)});
    spokes.push_back({seg.b, seg.a, s, std::atan2(a.y - b.y, a.x - b.x)});
  }
  std::sort(spokes.begin(), spokes.end(), [](const Spoke& p, const Spoke& q) {
    return p.vertex != q.vertex ? p.vertex < q.vertex : p.direction < q.direction;
  });
  std::optional<InputAngle> best;
  const auto consider = [&](const Spoke& p, const Spoke& q, double angle) {
    // The same segment listed twice, or two overlapping ones (the triangulation splits the
    // longer at the other's end): no angle at all.
    if (angle >= 180.0) return;  // no constraint: a straight or reflex corner
    if (p.other == q.other || (orient2d(in.points[p.vertex], in.points[p.other], in.points[q.other]) == 0.0 && angle < 90.0))
      return;
    if (!best || angle < best->degrees)
      best = InputAngle{angle, p.vertex, std::min(p.segment, q.segment), std::max(p.segment, q.segment)};
  };
  constexpr double kDegrees = 180.0 / std::numbers::pi;
  for (std::size_t i = 0; i < spokes.size();) {
    std::size_t j = i;
    while (j < spokes.size() && spokes[j].vertex == spokes[i].vertex) ++j;
    if (j - i >= 2) {
      for (std::size_t k = i; k + 1 < j; ++k)
        consider(spokes[k], spokes[k + 1], (spokes[k + 1].direction - spokes[k].direction) * kDegrees);
      // Round the back: from the last direction to the first, through +-pi.
      consider(spokes[j - 1], spokes[i], (2 * std::numbers::pi - (spokes[j - 1].direction - spokes[i].direction)) * kDegrees);
    }
    i = j;
  }
  return best;
}

}  // namespace meshstep
