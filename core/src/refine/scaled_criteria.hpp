// The criteria in the form the refinement loops test them: in the triangulation's scaled
// coordinates, squared, trigonometry done once.
#pragma once

#include <cstddef>
#include <functional>

#include "meshstep/geometry/point.hpp"
#include "meshstep/refine/region.hpp"

namespace meshstep::detail {

struct ScaledCriteria {
  double sin2_min_angle = 0.0;   // bad when below
  double cos_max_angle = -1.0;   // bad when below
  double max_aspect = 0.0;       // 0: none
  double max_area = 0.0;         // 0: none
  std::function<double(const Point&)> size;  // in scaled units; empty: none
  // The area bound of a triangle (its region's, the caller's); <= 0 or empty: none.
  std::function<double(const Point&, const Point&, const Point&)> max_area_for;
  double offcenter_beta = 0.0;   // radius-edge bound for off-centers
  // The diametral lens (Encroachment::lens): p encroaches on segment ab when the angle apb
  // is at least 180 - 2 theta, theta the angle bound (as Triangle); lens_cos2 is the square
  // of that angle's cosine: dot(a - p, b - p) < 0 and dot^2 >= lens_cos2 |a - p|^2 |b - p|^2.
  double lens_cos2 = 0.25;
  std::size_t max_triangles = 0, max_steiner = 0;
  // The run's region (RefineOptions::region, in the caller's coordinates), or none; and the
  // power of two that takes a scaled centroid back to the caller's coordinates (a product by
  // it is exact, as ldexp is, and much cheaper).
  const RefineRegion* region = nullptr;
  double unscale = 1.0;

  // An area or size bound, which decides where points go whatever their shapes.
  bool sized() const { return max_area > 0.0 || size || max_area_for; }
};

}  // namespace meshstep::detail
