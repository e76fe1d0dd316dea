// What a TIN is worth: its vertical error over every sample, and its angles in 3D.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <thread>
#include <vector>

#include "meshstep/terrain/tin.hpp"
#include "triangle_scan.hpp"

namespace meshstep::terrain {

namespace {

// The errors of the samples in rows [rows.first, rows.second], each once (`seen`, by
// sample: the samples on an edge are in two triangles).
struct BandError {
  double max = 0.0, sum2 = 0.0;
  std::size_t samples = 0;
};

BandError measure_band(const HeightGrid& grid, const Tin& tin, detail::RowRange rows, std::vector<std::uint8_t>& seen) {
  BandError band;
  for (auto t : tin.triangles) {
    detail::GridIndex corner[3];
    for (int k = 0; k < 3; ++k)
      corner[k] = {static_cast<std::int64_t>(tin.samples[t[k]] % grid.nx),
                   static_cast<std::int64_t>(tin.samples[t[k]] / grid.nx)};
    if (std::max({corner[0].j, corner[1].j, corner[2].j}) < rows.first ||
        std::min({corner[0].j, corner[1].j, corner[2].j}) > rows.second)
      continue;
    // From the smallest vertex id round, as the algorithm measures (tin_builder.hpp): the
    // same sums in the same order give the same last bits.
    int first = 0;
    while (t[first] > t[(first + 1) % 3] || t[first] > t[(first + 2) % 3]) ++first;
    const int second = (first + 1) % 3, third = (first + 2) % 3;
    detail::scan_errors(
        grid.z.data(), grid.nx, corner[first], corner[second], corner[third], tin.heights[t[first]],
        tin.heights[t[second]], tin.heights[t[third]],
        [&](std::size_t s, double e) {
          if (seen[s] || std::isnan(e)) return;  // NaN: no data
          seen[s] = 1;
          band.max = std::max(band.max, e);
          band.sum2 += e * e;
          ++band.samples;
        },
        rows);
  }
  return band;
}

}  // namespace

ErrorMeasure measure_error(const HeightGrid& grid, const Tin& tin) {
  // Two bands of rows, the upper one on a second thread when the grid is big: this check
  // of every sample runs after every approximation, and it was a tenth of one.
  std::vector<std::uint8_t> seen(grid.nx * grid.ny, 0);  // bytes: the bands write apart
  const auto middle = static_cast<std::int64_t>(grid.ny / 2);
  BandError lower, upper;
  const auto upper_band = [&] { upper = measure_band(grid, tin, {middle, detail::kAllRows.second}, seen); };
  if (seen.size() >= (std::size_t{1} << 20)) {
    std::thread helper(upper_band);
    lower = measure_band(grid, tin, {detail::kAllRows.first, middle - 1}, seen);
    helper.join();
  } else {
    upper_band();
    lower = measure_band(grid, tin, {detail::kAllRows.first, middle - 1}, seen);
  }
  ErrorMeasure m;
  m.max = std::max(lower.max, upper.max);
  m.samples = lower.samples + upper.samples;
  const double sum2 = lower.sum2 + upper.sum2;
  if (m.samples > 0) m.rms = std::sqrt(sum2 / static_cast<double>(m.samples));
  for (std::size_t s = 0; s < seen.size(); ++s) m.uncovered += !seen[s] && !std::isnan(grid.z[s]);
  return m;
}

AngleStats angle_stats_3d(const HeightGrid& grid, const Tin& tin) {
  AngleStats stats;
  stats.smallest_deg = tin.triangles.empty() ? 0.0 : 180.0;
  std::size_t under10 = 0, under20 = 0, under30 = 0;
  for (const auto& t : tin.triangles) {
    std::array<std::array<double, 3>, 3> p;
    for (int k = 0; k < 3; ++k) p[k] = vertex_position(grid, tin, t[k]);
    double smallest = 180.0;
    for (int k = 0; k < 3; ++k) {
      const auto& o = p[k];
      const auto& a = p[(k + 1) % 3];
      const auto& b = p[(k + 2) % 3];
      const double u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]};
      const double v[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]};
      const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
      const double cross[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      const double angle = std::atan2(std::hypot(cross[0], cross[1], cross[2]), dot) * 180.0 / std::numbers::pi;
      ++stats.histogram[std::min<std::size_t>(17, static_cast<std::size_t>(angle / 10.0))];
      smallest = std::min(smallest, angle);
    }
    stats.smallest_deg = std::min(stats.smallest_deg, smallest);
    under10 += smallest < 10.0;
    under20 += smallest < 20.0;
    under30 += smallest < 30.0;
  }
  if (!tin.triangles.empty()) {
    const double n = static_cast<double>(tin.triangles.size());
    stats.share_under_10 = under10 / n;
    stats.share_under_20 = under20 / n;
    stats.share_under_30 = under30 / n;
  }
  return stats;
}

}  // namespace meshstep::terrain
