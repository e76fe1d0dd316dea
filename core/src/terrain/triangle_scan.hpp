// Visits the grid samples a triangle covers, with their barycentric weights.
//
// A TIN's vertices are grid samples, so in the grid's index space (sample (i, j) at the
// point (i, j)) every corner is an integer point and every inside test is exact integer
// arithmetic: no sample is missed or taken twice by rounding. The triangle is closed:
// a sample on an edge is visited by both triangles that share it, which is harmless for
// the largest error (linear interpolation agrees along the shared edge).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
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
// sample's weights and 1 / (twice the area). One formula for the algorithm and for the
// measure of its result, so that a sample the algorithm found within the bound is within
// it when measured again, to the last bit. (A product, not a quotient: this runs for
// every sample of every triangle an insertion makes.)
inline double plane_height(std::int64_t wa, std::int64_t wb, std::int64_t wc, double za, double zb, double zc,
                           double inverse_area2) {
  return (static_cast<double>(wa) * za + static_cast<double>(wb) * zb + static_cast<double>(wc) * zc) *
         inverse_area2;
}

// How each weight changes from one column to the next: w(i + 1) = w(i) + step. (Callers
// name the three in plain variables: clang 15's lambdas cannot capture a structured binding.)
inline std::array<std::int64_t, 3> column_steps(GridIndex a, GridIndex b, GridIndex c) {
  return {-(c.j - b.j), -(a.j - c.j), -(b.j - a.j)};
}

// Calls visit_row(j, i_first, i_last, wa, wb, wc) for every row j that the counter-
// clockwise triangle abc crosses, with the columns of the samples inside or on it and the
// weights at i_first: wa + wb + wc = twice the area, and wa is a's weight (the edge
// function of the opposite edge bc); along the row, each weight grows by its column
// step (column_steps). Degenerate triangles visit nothing.
// Only the rows in [rows.first, rows.second] when given.
using RowRange = std::pair<std::int64_t, std::int64_t>;
inline constexpr RowRange kAllRows{std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()};

template <class VisitRow>
void scan_rows(GridIndex a, GridIndex b, GridIndex c, VisitRow&& visit_row, RowRange rows = kAllRows) {
  const std::int64_t area2 = edge_function(a, b, c);
  if (area2 <= 0) return;
  const std::int64_t j_lo = std::max(std::min({a.j, b.j, c.j}), rows.first);
  const std::int64_t j_hi = std::min(std::max({a.j, b.j, c.j}), rows.second);
  const std::int64_t i_lo = std::min({a.i, b.i, c.i}), i_hi = std::max({a.i, b.i, c.i});
  const std::array<std::int64_t, 3> steps = column_steps(a, b, c);
  const std::int64_t step_a = steps[0], step_b = steps[1], step_c = steps[2];
  for (std::int64_t j = j_lo; j <= j_hi; ++j) {
    const GridIndex row_start{i_lo, j};
    const std::int64_t wa = edge_function(b, c, row_start);
    const std::int64_t wb = edge_function(c, a, row_start);
    const std::int64_t wc = edge_function(a, b, row_start);
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
    visit_row(j, i_lo + first, i_lo + last, wa + step_a * first, wb + step_b * first, wc + step_c * first);
  }
}

// Calls visit(i, j, wa, wb, wc) for every sample (i, j) inside or on the triangle, row by
// row, columns ascending.
template <class Visit>
void scan_triangle(GridIndex a, GridIndex b, GridIndex c, Visit&& visit) {
  const std::array<std::int64_t, 3> steps = column_steps(a, b, c);
  const std::int64_t step_a = steps[0], step_b = steps[1], step_c = steps[2];
  scan_rows(a, b, c, [&](std::int64_t j, std::int64_t first, std::int64_t last, std::int64_t wa, std::int64_t wb,
                         std::int64_t wc) {
    for (std::int64_t i = first; i <= last; ++i) {
      visit(i, j, wa, wb, wc);
      wa += step_a;
      wb += step_b;
      wc += step_c;
    }
  });
}

// The columns of row j where the triangle's own corners stand (ascending, at most 3) and
// their heights. There the plane IS the corner's height, but its sums round: a vertex
// found a rounding-level error (5.55e-17) off its own plane looked worth inserting again
// under a bound of 0, and the run never ended. So the scans below measure a corner
// sample against its corner's height, exactly (an error of 0, or NaN without data), and
// pay for it only on the rows with a corner.
struct RowCorners {
  int count = 0;
  std::array<std::int64_t, 3> i{};
  std::array<double, 3> z{};
};
inline RowCorners corners_on_row(std::int64_t j, GridIndex a, GridIndex b, GridIndex c, double za, double zb,
                                 double zc) {
  RowCorners r;
  for (const auto& [p, z] : {std::pair{a, za}, std::pair{b, zb}, std::pair{c, zc}})
    if (p.j == j) {
      int k = r.count++;
      for (; k > 0 && r.i[k - 1] > p.i; --k) {
        r.i[k] = r.i[k - 1];
        r.z[k] = r.z[k - 1];
      }
      r.i[k] = p.i;
      r.z[k] = z;
    }
  return r;
}

// Calls visit(sample, error) for every sample inside or on the triangle abc of a grid of
// heights z (row-major, nx a row), its error measured against the
// plane through the corners' heights za, zb, zc. The one measure of the algorithm and of
// the check of its result, so that both agree to the last bit; the plane along a row is
// its value at the row's first sample plus a slope times the column offset. A sample
// without data (NaN) has a NaN error: `error > worst` is false for it, and a caller that
// sums errors must skip it.
template <class Visit>
void scan_errors(const float* z, std::size_t nx, GridIndex a, GridIndex b, GridIndex c, double za, double zb,
                 double zc, Visit&& visit, RowRange rows = kAllRows) {
  const double inverse_area2 = 1.0 / static_cast<double>(edge_function(a, b, c));
  const std::array<std::int64_t, 3> steps = column_steps(a, b, c);
  const std::int64_t step_a = steps[0], step_b = steps[1], step_c = steps[2];
  const double slope = plane_height(step_a, step_b, step_c, za, zb, zc, inverse_area2);
  scan_rows(a, b, c, [&](std::int64_t j, std::int64_t first, std::int64_t last, std::int64_t wa, std::int64_t wb,
                         std::int64_t wc) {
    const double start = plane_height(wa, wb, wc, za, zb, zc, inverse_area2);
    const std::size_t row = static_cast<std::size_t>(j) * nx;
    const auto plane_errors = [&](std::int64_t from, std::int64_t to) {  // columns [from, to)
      for (std::int64_t i = from; i < to; ++i) {
        const double height = z[row + static_cast<std::size_t>(i)];
        visit(row + static_cast<std::size_t>(i), std::abs(height - (start + slope * static_cast<double>(i - first))));
      }
    };
    const RowCorners corners = corners_on_row(j, a, b, c, za, zb, zc);
    std::int64_t from = first;
    for (int k = 0; k < corners.count; ++k) {
      const std::int64_t i = corners.i[k];
      plane_errors(from, i);
      const std::size_t s = row + static_cast<std::size_t>(i);
      visit(s, std::abs(static_cast<double>(z[s]) - corners.z[k]));
      from = i + 1;
    }
    plane_errors(from, last + 1);
  }, rows);
}

// The samples a search may take: columns [i_first, i_last] of rows [j_first, j_last].
// A tile's search leaves out its rectangle's border (tin.hpp, approximate_within_border).
struct SampleWindow {
  std::int64_t i_first, i_last, j_first, j_last;
};
// (Bounds far beyond any grid, yet far enough from the int64 limits that subtracting a
// column from them cannot overflow.)
inline constexpr std::int64_t kFarAway = std::int64_t{1} << 62;
inline constexpr SampleWindow kEverySample{-kFarAway, kFarAway, -kFarAway, kFarAway};

// The largest error among the samples with data inside or on the triangle abc, and its
// sample (error -1 and sample `none` when it holds no sample with data): scan_errors'
// arithmetic, to the bit, in a loop that keeps its running maximum in registers (through
// a visitor it went to memory on every sample, and this loop is most of a terrain run).
// Only the samples in `window`; each keeps the error it has in the whole row (the plane
// is still evaluated from the row's first sample), so that the measure agrees to the bit.
struct WorstSample {
  double error;
  std::size_t sample;
};
inline WorstSample worst_sample(const float* z, std::size_t nx, GridIndex a, GridIndex b, GridIndex c, double za,
                                double zb, double zc, std::size_t none, SampleWindow window = kEverySample) {
  const double inverse_area2 = 1.0 / static_cast<double>(edge_function(a, b, c));
  const std::array<std::int64_t, 3> steps = column_steps(a, b, c);
  const std::int64_t step_a = steps[0], step_b = steps[1], step_c = steps[2];
  const double slope = plane_height(step_a, step_b, step_c, za, zb, zc, inverse_area2);
  WorstSample worst{-1.0, none};
  scan_rows(a, b, c, [&](std::int64_t j, std::int64_t first, std::int64_t last, std::int64_t wa, std::int64_t wb,
                         std::int64_t wc) {
    const double start = plane_height(wa, wb, wc, za, zb, zc, inverse_area2);
    const float* row = z + static_cast<std::size_t>(j) * nx + static_cast<std::size_t>(first);
    const std::int64_t n = std::min(last, window.i_last) - first + 1;
    const std::int64_t k_first = std::max<std::int64_t>(0, window.i_first - first);
    double best = worst.error;
    std::int64_t best_k = -1;
    const auto take = [&](std::int64_t k, double error) {
      if (error > best) {  // false for NaN: no data
        best = error;
        best_k = k;
      }
    };
    const auto plane_errors = [&](std::int64_t from, std::int64_t to) {  // offsets [from, to)
      for (std::int64_t k = from; k < to; ++k)
        take(k, std::abs(static_cast<double>(row[k]) - (start + slope * static_cast<double>(k))));
    };
    const RowCorners corners = corners_on_row(j, a, b, c, za, zb, zc);
    std::int64_t from = k_first;
    for (int m = 0; m < corners.count; ++m) {
      const std::int64_t k = corners.i[m] - first;
      if (k < from || k >= n) continue;  // outside the window
      plane_errors(from, k);
      take(k, std::abs(static_cast<double>(row[k]) - corners.z[m]));
      from = k + 1;
    }
    plane_errors(from, n);
    if (best_k >= 0) worst = {best, static_cast<std::size_t>(j) * nx + static_cast<std::size_t>(first + best_k)};
  }, RowRange{window.j_first, window.j_last});
  return worst;
}

}  // namespace meshstep::terrain::detail
