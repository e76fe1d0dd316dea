// Visits the grid samples a triangle covers, with their barycentric weights.
//
// A TIN's vertices are grid samples, so in the grid's index space (sample (i, j) at the
// point (i, j)) every corner is an integer point and every inside test is exact integer
// arithmetic: no sample is missed or taken twice by rounding. The triangle is closed:
// a sample on an edge is visited by both triangles that share it, which is harmless for
// the largest error (linear interpolation agrees along the shared edge).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>

namespace meshstep::terrain::detail {

struct GridIndex {
  std::int64_t i, j;  // column, row
};

// Twice the signed area of (a, b, p): positive when p is left of a -> b.
inline std::int64_t edge_function(GridIndex a, GridIndex b, GridIndex p) {
  return (b.i - a.i) * (p.j - a.j) - (b.j - a.j) * (p.i - a.i);
}

// floor(n / d) and ceil(n / d) for d > 0, exact on integers of either sign.
inline std::int64_t floor_div(std::int64_t n, std::int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); }
inline std::int64_t ceil_div(std::int64_t n, std::int64_t d) { return -floor_div(-n, d); }

// The height at a sample of the plane through the corners' heights za, zb, zc, from the
// sample's weights. One formula for the algorithm and for the measure of its result, so
// that a sample the algorithm found within the bound is within it when measured again.
inline double plane_height(std::int64_t wa, std::int64_t wb, std::int64_t wc, double za, double zb, double zc,
                           std::int64_t area2) {
  return (static_cast<double>(wa) * za + static_cast<double>(wb) * zb + static_cast<double>(wc) * zc) /
         static_cast<double>(area2);
}

// Calls visit(i, j, wa, wb, wc) for every sample (i, j) inside or on the counter-clockwise
// triangle abc, row by row, columns ascending; wa + wb + wc = twice the area, and wa is
// a's weight (the edge function of the opposite edge bc). Degenerate triangles visit
// nothing.
template <class Visit>
void scan_triangle(GridIndex a, GridIndex b, GridIndex c, Visit&& visit) {
  const std::int64_t area2 = edge_function(a, b, c);
  if (area2 <= 0) return;
  const std::int64_t j_lo = std::min({a.j, b.j, c.j}), j_hi = std::max({a.j, b.j, c.j});
  const std::int64_t i_lo = std::min({a.i, b.i, c.i}), i_hi = std::max({a.i, b.i, c.i});
  // Each weight is linear in i along a row: w(i) = w(i_lo) + step * (i - i_lo).
  const std::int64_t step_a = -(c.j - b.j), step_b = -(a.j - c.j), step_c = -(b.j - a.j);
  for (std::int64_t j = j_lo; j <= j_hi; ++j) {
    const GridIndex row_start{i_lo, j};
    std::int64_t wa = edge_function(b, c, row_start);
    std::int64_t wb = edge_function(c, a, row_start);
    std::int64_t wc = edge_function(a, b, row_start);
    // The columns where all three weights are >= 0, from each weight's sign change.
    std::int64_t first = 0, last = i_hi - i_lo;
    bool empty = false;
    for (const auto& [w, step] : {std::pair{wa, step_a}, std::pair{wb, step_b}, std::pair{wc, step_c}}) {
      if (step > 0) {
        first = std::max(first, ceil_div(-w, step));
      } else if (step < 0) {
        last = std::min(last, floor_div(w, -step));
      } else if (w < 0) {
        empty = true;
      }
    }
    if (empty || first > last) continue;
    wa += step_a * first;
    wb += step_b * first;
    wc += step_c * first;
    for (std::int64_t k = first; k <= last; ++k) {
      visit(i_lo + k, j, wa, wb, wc);
      wa += step_a;
      wb += step_b;
      wc += step_c;
    }
  }
}

}  // namespace meshstep::terrain::detail
