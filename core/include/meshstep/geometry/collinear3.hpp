// Exact collinearity of three points in 3D, the test that decides a degenerate triangle
// everywhere (the surface report, bisection's cuts, the flips): rounding must not let one
// part of the library make a triangle that another part calls degenerate.
#pragma once

#include "meshstep/geometry/point3.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep {

// Their cross product is zero, and its three components are the orientations of the points
// projected on the yz, zx and xy planes, which the exact 2D predicate decides without
// rounding error (for coordinates whose products neither overflow nor underflow: see
// geometry/predicates.hpp and the range rule).
inline bool collinear(const Point3& a, const Point3& b, const Point3& c) {
  return orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == 0.0 &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == 0.0 &&
         orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == 0.0;
}

}  // namespace meshstep
