// Shape measures of one triangle, and the quality tests the stopping criteria use.
//
// The tests avoid trigonometry and square roots in the refinement loop: the smallest angle
// theta of a triangle with area A and edges l_min <= l_1 <= l_2 satisfies
// sin(theta) = 2A / (l_1 l_2), so "theta < alpha" is 4A^2 < sin^2(alpha) l_1^2 l_2^2.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "meshstep/geometry/point.hpp"

namespace meshstep::quality {

inline double squared_distance(const Point& a, const Point& b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

inline double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
inline double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Twice the signed area (positive for a counterclockwise triangle), in floating point: for
// measuring, not for deciding topology.
inline double twice_area(const Point& a, const Point& b, const Point& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Everything the criteria look at, from one pass over the three edges.
struct Shape {
  double area = 0.0;             // positive for counterclockwise
  double shortest2 = 0.0;        // squared edge lengths, sorted
  double middle2 = 0.0;
  double longest2 = 0.0;
  int shortest_edge = 0;         // edge i runs from vertex i to vertex (i + 1) % 3
  int longest_edge = 0;

  // sin^2 of the smallest angle (opposite the shortest edge).
  double sin2_min_angle() const {
    const double d = middle2 * longest2;
    return d > 0.0 ? 4.0 * area * area / d : 0.0;
  }
  // cos of the largest angle (opposite the longest edge), by the law of cosines.
  double cos_max_angle() const {
    const double d = 2.0 * std::sqrt(shortest2 * middle2);
    return d > 0.0 ? (shortest2 + middle2 - longest2) / d : -1.0;
  }
  double min_angle_deg() const { return degrees(std::asin(std::min(1.0, std::sqrt(sin2_min_angle())))); }
  double max_angle_deg() const { return degrees(std::acos(std::clamp(cos_max_angle(), -1.0, 1.0))); }
  // Aspect ratio, as the criteria use it: longest edge over the shortest altitude,
  // l_max^2 / (2A). An equilateral triangle has 2/sqrt(3) = 1.1547; degenerate ones infinity.
  double aspect() const { return area > 0.0 ? longest2 / (2.0 * area) : INFINITY; }
  // Circumradius over shortest edge (Ruppert's and Triangle's measure): 1/(2 sin theta_min).
  double radius_edge() const {
    const double s = sin2_min_angle();
    return s > 0.0 ? 0.5 / std::sqrt(s) : INFINITY;
  }
};

[[gnu::always_inline]] inline Shape shape(const Point& a, const Point& b, const Point& c) {
  Shape s;
  s.area = 0.5 * twice_area(a, b, c);
  const double l[3] = {squared_distance(a, b), squared_distance(b, c), squared_distance(c, a)};
  int lo = 0, hi = 0;
  for (int i = 1; i < 3; ++i) {
    if (l[i] < l[lo]) lo = i;
    if (l[i] >= l[hi]) hi = i;
  }
  if (lo == hi) hi = (lo + 1) % 3;  // all equal
  s.shortest_edge = lo;
  s.longest_edge = hi;
  s.shortest2 = l[lo];
  s.longest2 = l[hi];
  s.middle2 = l[3 - lo - hi];
  return s;
}

// The circumcenter of a nondegenerate triangle, relative to a for accuracy.
inline Point circumcenter(const Point& a, const Point& b, const Point& c) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double d = 2.0 * (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

}  // namespace meshstep::quality
