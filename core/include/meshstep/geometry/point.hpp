// Plain 2D point and bounding box: the only geometric value types of the core.
#pragma once

#include <algorithm>
#include <limits>

namespace meshstep {

struct Point {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point&, const Point&) = default;
};

// Lexicographic (x, then y) order: the fixed total order used wherever ties must be
// broken independently of vertex numbering (symbolic perturbation, canonical output).
inline bool lex_less(const Point& a, const Point& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

struct BBox {
  Point lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Point hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  void add(const Point& p) {
    lo.x = std::min(lo.x, p.x);
    lo.y = std::min(lo.y, p.y);
    hi.x = std::max(hi.x, p.x);
    hi.y = std::max(hi.y, p.y);
  }
  bool empty() const { return lo.x > hi.x; }
};

}  // namespace meshstep
