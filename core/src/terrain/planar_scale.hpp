// The range rule (geometry/magnitudes.hpp) for a height grid: the power of two that brings
// its sample positions into the window where the predicates are exact, or an error when
// no power of two can.
#pragma once

#include <cmath>
#include <string>

#include "meshstep/error.hpp"
#include "meshstep/geometry/magnitudes.hpp"
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/terrain/height_grid.hpp"

namespace meshstep::terrain::detail {

// The sample spacing scaled by 2^exponent: sample (i, j) is at (i * dx, j * dy) in the
// triangulation, exactly 2^exponent times its place in metres (a power of two changes no
// predicate). Planar Delaunay is the same at every scale; what mixes in heights (3D
// lengths and angles) stays in metres.
struct PlanarScale {
  int exponent = 0;
  double dx = 0.0, dy = 0.0;
};

// Throws InputError for a grid smaller than 2 x 2, when the grid's far corner is beyond the doubles (a cell size of 1e308
// on three samples), or when dx and dy are too far apart in magnitude for exact predicates.
inline PlanarScale planar_scale(const HeightGrid& g) {
  if (g.nx < 2 || g.ny < 2) throw InputError("a terrain needs a grid of at least 2 x 2 samples");
  const double x = static_cast<double>(g.nx - 1) * g.dx, y = static_cast<double>(g.ny - 1) * g.dy;
  if (!std::isfinite(x) || !std::isfinite(y))
    throw InputError("the grid's extent, " + std::to_string(g.nx - 1) + " x " + io::shortest_text(g.dx) + " by " +
                     std::to_string(g.ny - 1) + " x " + io::shortest_text(g.dy) +
                     " m, is beyond the largest double (1.8e308)");
  const Point positions[] = {{g.dx, g.dy}, {x, y}};
  const Magnitudes m = magnitudes(positions);
  if (!m.within_span())
    throw InputError("the cell sides " + io::shortest_text(g.dx) + " and " + io::shortest_text(g.dy) + " m are more than 2^" +
                     std::to_string(kSpanExponent) + " apart in magnitude with the grid's extent; meshstep computes "
                     "exactly only within that span");
  const int e = m.scale_exponent();
  return {e, std::ldexp(g.dx, e), std::ldexp(g.dy, e)};
}

}  // namespace meshstep::terrain::detail
