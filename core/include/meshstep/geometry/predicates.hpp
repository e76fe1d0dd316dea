// Exact geometric predicates.
//
// Each predicate first evaluates its determinant in double precision together with a
// bound on the rounding error (Shewchuk 1997, stage A); only when the sign is not certified
// does it fall back to exact floating-point expansion arithmetic. The fallback is correct
// for any finite input whose intermediate products neither overflow nor underflow
// (coordinates within about 1e±70 of each other for incircle); callers that may see
// extreme magnitudes rescale by a power of two first (exact).
#pragma once

#include "meshstep/geometry/point.hpp"

namespace meshstep {

// > 0 when a, b, c turn counterclockwise, < 0 clockwise, 0 when collinear.
// The magnitude is an approximation of twice the signed area; only the sign is exact.
double orient2d(const Point& a, const Point& b, const Point& c);

// > 0 when d lies strictly inside the circle through a, b, c (which must be
// counterclockwise), < 0 strictly outside, 0 on it. Only the sign is exact.
double incircle(const Point& a, const Point& b, const Point& c, const Point& d);

// Sign (-1, 0, +1) of incircle under symbolic perturbation: the lifted coordinate
// x²+y² of each point is raised by an infinitesimal that is larger for points earlier in
// lexicographic order. Never 0 unless all four points are collinear, so the Delaunay
// triangulation of any point set (cocircular grids included) becomes unique and every
// insertion strategy and data structure reaches the same one.
int incircle_perturbed(const Point& a, const Point& b, const Point& c, const Point& d);

// Exact-sign helpers for collinear points: is c strictly between a and b on their line?
bool strictly_between(const Point& a, const Point& b, const Point& c);

}  // namespace meshstep
