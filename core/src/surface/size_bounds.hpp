// The size bounds of a surface refinement (surface_refine.hpp: the longest edge, the area)
// as one measure of a triangle, shared by the bisection that meets them and the flips that
// must not undo them: both then agree to the last bit on which triangles break a bound.
#pragma once

#include <algorithm>

#include "meshstep/geometry/point3.hpp"
#include "surface_geometry.hpp"

namespace meshstep::surface::detail {

class SizeBounds {
 public:
  SizeBounds(double max_edge, double max_area)
      : max_edge_(max_edge), max_edge_squared_(max_edge * max_edge), max_area_(max_area) {}

  bool any() const { return max_edge_ > 0.0 || max_area_ > 0.0; }

  // How far the triangle abc is over its bounds: 0 when it meets them all, else the
  // largest of (longest edge / max_edge)^2 and area / max_area, both squared ratios of
  // sizes, over 1. The caller passes the corners from the smallest vertex id, so that one
  // triangle gets one value whoever measures it.
  double excess(const Point3& a, const Point3& b, const Point3& c) const {
    double e = 0.0;
    if (max_edge_ > 0.0) {
      const double longest = std::max({squared_length(a, b), squared_length(b, c), squared_length(c, a)});
      if (longest > max_edge_squared_) e = longest / max_edge_squared_;
    }
    if (max_area_ > 0.0) {
      const double s = area(a, b, c);
      if (s > max_area_) e = std::max(e, s / max_area_);
    }
    return e;
  }

  bool edge_over(const Point3& a, const Point3& b, const Point3& c) const {
    return max_edge_ > 0.0 &&
           std::max({squared_length(a, b), squared_length(b, c), squared_length(c, a)}) > max_edge_squared_;
  }
  bool area_over(const Point3& a, const Point3& b, const Point3& c) const {
    return max_area_ > 0.0 && area(a, b, c) > max_area_;
  }

 private:
  double max_edge_, max_edge_squared_, max_area_;
};

}  // namespace meshstep::surface::detail
