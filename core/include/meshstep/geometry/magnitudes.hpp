// The range of magnitudes meshstep computes in exactly, and the power of two that brings
// coordinates into it.
//
// The predicates' expansions are exact while no product underflows or overflows: incircle
// multiplies four coordinate differences, and its expansions' smallest terms are about
// 2^-159 of such a product. With every nonzero |coordinate| in [2^kLowestExponent,
// 2^kHighestExponent), the differences of distinct points lie in [2^-199, 2^201], the
// products in [2^-796, 2^804] and their smallest terms above 2^-955: inside the normal
// doubles. Coordinates whose nonzero magnitudes span at most 2^kSpanExponent are scaled
// there, by a power of two, which is exact and changes no predicate; a wider span is
// refused by the triangulators and reported by the checker.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>

#include "meshstep/geometry/point.hpp"

namespace meshstep {

inline constexpr int kLowestExponent = -147;
inline constexpr int kHighestExponent = 200;
inline constexpr int kSpanExponent = 140;

struct Magnitudes {
  double largest = 0.0, smallest = 0.0;         // of the nonzero |coordinates| (0: none)
  std::size_t largest_at = 0, smallest_at = 0;  // the point each comes from

  // Takes in the magnitudes of more points, numbered from `offset` on.
  void merge(const Magnitudes& more, std::size_t offset) {
    if (more.largest > largest) largest = more.largest, largest_at = more.largest_at + offset;
    if (more.smallest != 0.0 && (smallest == 0.0 || more.smallest < smallest))
      smallest = more.smallest, smallest_at = more.smallest_at + offset;
  }
  // Do the nonzero magnitudes lie within 2^kSpanExponent of each other?
  bool within_span() const { return largest == 0.0 || std::ilogb(largest) - std::ilogb(smallest) <= kSpanExponent; }
  // The exponent e such that scaling by 2^e brings every nonzero coordinate into the window:
  // 0 when they are in it already (most inputs), else the one that brings the largest
  // near 1.
  int scale_exponent() const {
    if (largest == 0.0) return 0;
    const int high = std::ilogb(largest), low = std::ilogb(smallest);
    return (high < kHighestExponent && low >= kLowestExponent) ? 0 : -high;
  }
};

inline Magnitudes magnitudes(std::span<const Point> points) {
  Magnitudes m;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (const double c : {std::fabs(points[i].x), std::fabs(points[i].y)}) {
      if (c == 0.0 || !std::isfinite(c)) continue;
      if (c > m.largest) m.largest = c, m.largest_at = i;
      if (m.smallest == 0.0 || c < m.smallest) m.smallest = c, m.smallest_at = i;
    }
  return m;
}

// The range new points must keep to: a nonzero coordinate below 2^-kSpanExponent of the
// largest input coordinate would take the mesh out of the span where the predicates are
// exact (and where the checker can check it). Refinement meets it only where features
// shrink towards a point 1e-30 from a line through unit coordinates, say: the split or
// insertion is refused there, as for a subsegment a few ulps long. Segment insertion meets
// it where two segments of unit size cross among coordinates of 1e41: the input is refused.
class ExactRange {
 public:
  explicit ExactRange(std::span<const Point> inputs) {
    const Magnitudes m = magnitudes(inputs);
    floor_ = m.largest == 0.0 ? 0.0 : std::ldexp(1.0, std::ilogb(m.largest) - kSpanExponent);
  }
  bool holds(const Point& p) const { return fits(p.x) && fits(p.y); }

 private:
  bool fits(double c) const { return c == 0.0 || std::fabs(c) >= floor_; }
  double floor_ = 0.0;
};

}  // namespace meshstep
