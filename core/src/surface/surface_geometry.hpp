// Measures of 3D triangles for surface bisection: lengths, areas, angles, midpoints.
//
// Every measure of a triangle is taken with its corners in one fixed rotation (the caller
// starts from the smallest vertex id), so that the same triangle gets bit-identical values
// whichever data structure stored it and whichever corner it happened to list first.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "meshstep/geometry/point3.hpp"

namespace meshstep::surface::detail {

inline double squared_length(const Point3& a, const Point3& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
  return dx * dx + dy * dy + dz * dz;
}

// Halving each sum is exact, so the midpoint is the correctly rounded one: it lies on the
// edge up to that rounding, which is what keeps the area (to the last few bits).
inline Point3 midpoint(const Point3& a, const Point3& b) {
  return {(a.x + b.x) / 2.0, (a.y + b.y) / 2.0, (a.z + b.z) / 2.0};
}

inline double area(const Point3& a, const Point3& b, const Point3& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  return 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
}

// The angle at o between the rays to p and q, by atan2 of |cross| and dot: accurate for
// angles near 0 and near 180 degrees alike, where acos of a cosine is not.
inline double angle_deg(const Point3& o, const Point3& p, const Point3& q) {
  const double ux = p.x - o.x, uy = p.y - o.y, uz = p.z - o.z;
  const double vx = q.x - o.x, vy = q.y - o.y, vz = q.z - o.z;
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const double cross = std::sqrt(nx * nx + ny * ny + nz * nz);
  return std::atan2(cross, ux * vx + uy * vy + uz * vz) * (180.0 / std::numbers::pi);
}

// The smallest angle is the one facing the shortest edge: one atan2 instead of three.
inline double smallest_angle_deg(const Point3& a, const Point3& b, const Point3& c) {
  const double ab = squared_length(a, b), bc = squared_length(b, c), ca = squared_length(c, a);
  if (ab <= bc && ab <= ca) return angle_deg(c, a, b);
  if (bc <= ca) return angle_deg(a, b, c);
  return angle_deg(b, c, a);
}

// A sum of many positive terms without the drift of plain addition (Neumaier's variant of
// Kahan summation): a million triangle areas add up to within an ulp or two, so "the area
// did not change" can be checked to 1e-12 and mean it.
class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    compensation_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

}  // namespace meshstep::surface::detail
