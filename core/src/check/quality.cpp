// Angle statistics and the canonical triangle list.
#include "meshstep/check/quality.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace meshstep {
namespace {

// Unsigned angle at p, from atan2 of |cross| and dot: accurate for tiny and near-straight
// angles alike, where acos of a normalized dot product loses most of its digits.
double corner_deg(const Point& p, const Point& q, const Point& r) {
  const double ux = q.x - p.x, uy = q.y - p.y;
  const double vx = r.x - p.x, vy = r.y - p.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * (180.0 / std::numbers::pi);
}

std::array<double, 3> angles(const Point& a, const Point& b, const Point& c) {
  return {corner_deg(a, b, c), corner_deg(b, c, a), corner_deg(c, a, b)};
}

}  // namespace

double triangle_min_angle_deg(const Point& a, const Point& b, const Point& c) {
  const auto t = angles(a, b, c);
  return std::min({t[0], t[1], t[2]});
}

double triangle_max_angle_deg(const Point& a, const Point& b, const Point& c) {
  const auto t = angles(a, b, c);
  return std::max({t[0], t[1], t[2]});
}

AngleStats angle_stats(const TriMesh& mesh) {
  AngleStats stats;
  bool any = false;
  for (const auto& tri : mesh.triangles) {
    if (tri[0] >= mesh.points.size() || tri[1] >= mesh.points.size() ||
        tri[2] >= mesh.points.size())
      continue;
    const auto t = angles(mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]);
    const double lo = std::min({t[0], t[1], t[2]}), hi = std::max({t[0], t[1], t[2]});
    stats.min_angle_deg = any ? std::min(stats.min_angle_deg, lo) : lo;
    stats.max_angle_deg = any ? std::max(stats.max_angle_deg, hi) : hi;
    any = true;
  }
  return stats;
}

std::vector<std::array<std::uint32_t, 3>> canonical_triangles(const TriMesh& mesh) {
  std::vector<std::array<std::uint32_t, 3>> result;
  result.reserve(mesh.triangles.size());
  for (const auto& tri : mesh.triangles) {
    // Rotation, not sorting: (0 1 2) and (0 2 1) are opposite orientations, not equal.
    const auto first = std::min_element(tri.begin(), tri.end()) - tri.begin();
    result.push_back({tri[first], tri[(first + 1) % 3], tri[(first + 2) % 3]});
  }
  std::sort(result.begin(), result.end());
  return result;
}

}  // namespace meshstep
