// Exact geometric predicates.
//
// Each predicate first evaluates its determinant in double precision together with a
// bound on the rounding error (Shewchuk 1997, stage A); only when the sign is not certified
// does it fall back to exact floating-point expansion arithmetic. The fallback is correct
// for any finite input whose intermediate products neither overflow nor underflow
// (coordinates within about 1e±70 of each other for incircle); callers that may see
// extreme magnitudes rescale by a power of two first (exact).
#pragma once

#include <cmath>

#include "meshstep/geometry/point.hpp"

namespace meshstep {

namespace detail {
// Exact evaluations, out of line: the filters below settle almost every call.
double orient2d_exact(const Point& a, const Point& b, const Point& c);
double incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d);
int incircle_tie_break(const Point& a, const Point& b, const Point& c, const Point& d);

inline constexpr double kEpsilon = 0x1p-53;  // unit roundoff of double
inline constexpr double kOrientErrBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
inline constexpr double kInCircleErrBound = (10.0 + 96.0 * kEpsilon) * kEpsilon;
}  // namespace detail

// > 0 when a, b, c turn counterclockwise, < 0 clockwise, 0 when collinear.
// The magnitude is an approximation of twice the signed area; only the sign is exact.
[[gnu::always_inline]] inline double orient2d(const Point& a, const Point& b, const Point& c) {
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  // Terms of opposite signs cannot cancel: the rounded difference has the right sign.
  if ((detleft > 0.0 && detright <= 0.0) || (detleft < 0.0 && detright >= 0.0)) return det;
  const double bound = detail::kOrientErrBound * std::fabs(detleft + detright);
  if (det > bound || -det > bound) return det;
  if (detleft == 0.0 && detright == 0.0) return 0.0;
  return detail::orient2d_exact(a, b, c);
}

// Twice the signed area of a, b, c as orient2d's, but with its magnitude too computed from
// the exact value: within a few ulps of it, where orient2d's double evaluation may be off by
// all its digits (coordinates of 1e16 next to ones of 1). Out of line and far slower: for
// the rare places that compute with the value, such as a crossing point.
double orient2d_value(const Point& a, const Point& b, const Point& c);

// > 0 when d lies strictly inside the circle through a, b, c (which must be
// counterclockwise), < 0 strictly outside, 0 on it. Only the sign is exact.
[[gnu::always_inline]] inline double incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) +
                     clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  const double bound = detail::kInCircleErrBound * permanent;
  if (det > bound || -det > bound) return det;
  return detail::incircle_exact(a, b, c, d);
}

// Sign (-1, 0, +1) of incircle under symbolic perturbation: the lifted coordinate
// x²+y² of each point is raised by an infinitesimal that is larger for points earlier in
// lexicographic order. Never 0 unless all four points are collinear, so the Delaunay
// triangulation of any point set (cocircular grids included) becomes unique and every
// insertion strategy and data structure reaches the same one.
[[gnu::always_inline]] inline int incircle_perturbed(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double s = incircle(a, b, c, d);
  if (s > 0.0) return 1;
  if (s < 0.0) return -1;
  return detail::incircle_tie_break(a, b, c, d);
}

// Exact-sign helpers for collinear points: is c strictly between a and b on their line?
inline bool strictly_between(const Point& a, const Point& b, const Point& c) {
  if (a.x != b.x) return (a.x < c.x && c.x < b.x) || (b.x < c.x && c.x < a.x);
  return (a.y < c.y && c.y < b.y) || (b.y < c.y && c.y < a.y);
}

}  // namespace meshstep
