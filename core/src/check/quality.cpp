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

namespace {

// A monotone stand-in for the angle of (x >= 0 ... any, y >= 0), from 0 (along +x) to 2 (along
// -x), without the arctangent: the corners are ranked by it, and only the smallest's and
// the largest's angles are computed (atan2 was three quarters of the statistics' time).
double pseudo_angle(double y, double x) {
  const double sum = y + std::fabs(x);
  if (sum == 0.0) return 0.0;  // a corner of coincident points: atan2(0, 0) == 0
  return x >= 0.0 ? y / sum : 2.0 - y / sum;
}

struct Corner {
  double rank;
  const Point *p, *q, *r;
};

}  // namespace

AngleStats angle_stats(const TriMesh& mesh) {
  AngleStats stats;
  Corner lo{INFINITY, nullptr, nullptr, nullptr}, hi{-INFINITY, nullptr, nullptr, nullptr};
  const auto& pts = mesh.points;
  for (const auto& tri : mesh.triangles) {
    if (tri[0] >= pts.size() || tri[1] >= pts.size() || tri[2] >= pts.size()) continue;
    const Point* v[3] = {&pts[tri[0]], &pts[tri[1]], &pts[tri[2]]};
    for (int i = 0; i < 3; ++i) {
      const Point &p = *v[i], &q = *v[(i + 1) % 3], &r = *v[(i + 2) % 3];
      const double ux = q.x - p.x, uy = q.y - p.y, vx = r.x - p.x, vy = r.y - p.y;
      const double rank = pseudo_angle(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
      if (rank < lo.rank) lo = {rank, &p, &q, &r};
      if (rank > hi.rank) hi = {rank, &p, &q, &r};
    }
  }
  if (lo.p) stats.min_angle_deg = corner_deg(*lo.p, *lo.q, *lo.r);
  if (hi.p) stats.max_angle_deg = corner_deg(*hi.p, *hi.q, *hi.r);
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
