// A piecewise-constant field over a set of triangles: at a point, the value of a triangle
// that holds it; over a triangle, the smallest positive value of the triangles it overlaps.
// Refinement reads area bounds from one built on the starting mesh (per region) or on the
// mesh being re-refined (per triangle, from its .area): a new triangle must meet the bound
// of every old triangle it overlaps, even one that holds none of its points' samples.
//
// A uniform grid of about one cell per triangle, each cell listing the triangles whose
// bounding box meets it; a query tests the few triangles of one cell exactly.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep {

class TriangleField {
 public:
  void add(const Point& a, const Point& b, const Point& c, double value) { triangles_.push_back({{a, b, c}, value}); }
  bool empty() const { return triangles_.empty(); }

  // Call once after the last add().
  void build() {
    if (triangles_.empty()) return;
    lo_ = hi_ = triangles_.front().corners[0];
    for (const Triangle& t : triangles_)
      for (const Point& p : t.corners) {
        lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y)};
        hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y)};
      }
    side_ = static_cast<std::uint32_t>(std::clamp(std::sqrt(static_cast<double>(triangles_.size())), 1.0, 4096.0));
    cells_.assign(static_cast<std::size_t>(side_) * side_ + 1, 0);
    // Two passes (count, then fill) into one flat array: no vector per cell.
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        for (std::size_t i = 1; i < cells_.size(); ++i) cells_[i] += cells_[i - 1];
        members_.resize(cells_.back());
      }
      for (std::uint32_t i = 0; i < triangles_.size(); ++i) {
        const auto& c = triangles_[i].corners;
        const std::uint32_t x0 = column(std::min({c[0].x, c[1].x, c[2].x})), x1 = column(std::max({c[0].x, c[1].x, c[2].x}));
        const std::uint32_t y0 = row(std::min({c[0].y, c[1].y, c[2].y})), y1 = row(std::max({c[0].y, c[1].y, c[2].y}));
        for (std::uint32_t y = y0; y <= y1; ++y)
          for (std::uint32_t x = x0; x <= x1; ++x) {
            const std::size_t cell = static_cast<std::size_t>(y) * side_ + x;
            if (pass == 0) ++cells_[cell + 1];
            else members_[cells_[cell]++] = i;
          }
      }
      if (pass == 1) {  // the fill advanced each start to the next cell's: shift back
        for (std::size_t i = cells_.size() - 1; i > 0; --i) cells_[i] = cells_[i - 1];
        cells_[0] = 0;
      }
    }
  }

  // The smallest positive value among the triangles whose interior meets the interior of
  // the counterclockwise triangle (a, b, c); `none` if there is none.
  double min_positive_over(const Point& a, const Point& b, const Point& c, double none) const {
    if (triangles_.empty()) return none;
    const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
    const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
    if (x1 < lo_.x || x0 > hi_.x || y1 < lo_.y || y0 > hi_.y) return none;
    const std::array<Point, 3> query{a, b, c};
    double best = none;
    for (std::uint32_t y = row(y0); y <= row(y1); ++y)
      for (std::uint32_t x = column(x0); x <= column(x1); ++x) {
        const std::size_t cell = static_cast<std::size_t>(y) * side_ + x;
        for (std::uint32_t k = cells_[cell]; k < cells_[cell + 1]; ++k) {
          const Triangle& t = triangles_[members_[k]];
          if (!(t.value > 0.0) || (best > 0.0 && t.value >= best)) continue;
          if (interiors_meet(t.corners, query)) best = t.value;
        }
      }
    return best;
  }

  // The value of a triangle holding p (closed: on an edge counts), or `outside`.
  double at(const Point& p, double outside) const {
    if (triangles_.empty() || p.x < lo_.x || p.x > hi_.x || p.y < lo_.y || p.y > hi_.y) return outside;
    const std::size_t cell = static_cast<std::size_t>(row(p.y)) * side_ + column(p.x);
    for (std::uint32_t k = cells_[cell]; k < cells_[cell + 1]; ++k) {
      const Triangle& t = triangles_[members_[k]];
      const auto& c = t.corners;
      if (orient2d(c[0], c[1], p) >= 0.0 && orient2d(c[1], c[2], p) >= 0.0 && orient2d(c[2], c[0], p) >= 0.0)
        return t.value;
    }
    return outside;
  }

 private:
  struct Triangle {
    std::array<Point, 3> corners;  // counterclockwise
    double value;
  };

  // Two counterclockwise triangles overlap in their interiors unless an edge of one has the
  // whole other on its outer side (touching along an edge or at a vertex is not overlap).
  static bool separated_by_an_edge_of(const std::array<Point, 3>& s, const std::array<Point, 3>& t) {
    for (int i = 0; i < 3; ++i) {
      const Point &p = s[i], &q = s[(i + 1) % 3];
      if (orient2d(p, q, t[0]) <= 0.0 && orient2d(p, q, t[1]) <= 0.0 && orient2d(p, q, t[2]) <= 0.0) return true;
    }
    return false;
  }
  static bool interiors_meet(const std::array<Point, 3>& s, const std::array<Point, 3>& t) {
    return !separated_by_an_edge_of(s, t) && !separated_by_an_edge_of(t, s);
  }

  std::uint32_t index(double v, double lo, double hi) const {
    if (!(hi > lo)) return 0;
    const double f = (v - lo) / (hi - lo) * side_;
    return static_cast<std::uint32_t>(std::clamp(f, 0.0, static_cast<double>(side_ - 1)));
  }
  std::uint32_t column(double x) const { return index(x, lo_.x, hi_.x); }
  std::uint32_t row(double y) const { return index(y, lo_.y, hi_.y); }

  std::vector<Triangle> triangles_;
  Point lo_{0, 0}, hi_{0, 0};
  std::uint32_t side_ = 1;
  std::vector<std::uint32_t> cells_;    // prefix offsets into members_, side_ * side_ + 1
  std::vector<std::uint32_t> members_;  // triangle indices by cell
};

}  // namespace meshstep
