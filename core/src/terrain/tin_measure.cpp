// What a TIN is worth: its vertical error over every sample, and its angles in 3D.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "meshstep/terrain/tin.hpp"
#include "triangle_scan.hpp"

namespace meshstep::terrain {

ErrorMeasure measure_error(const HeightGrid& grid, const Tin& tin) {
  ErrorMeasure m;
  std::vector<bool> seen(grid.nx * grid.ny, false);
  double sum2 = 0.0;
  for (const auto& t : tin.triangles) {
    detail::GridIndex corner[3];
    double z[3];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t s = tin.samples[t[k]];
      corner[k] = {static_cast<std::int64_t>(s % grid.nx), static_cast<std::int64_t>(s / grid.nx)};
      z[k] = tin.heights[t[k]];
    }
    const std::int64_t area2 = detail::edge_function(corner[0], corner[1], corner[2]);
    detail::scan_triangle(corner[0], corner[1], corner[2],
                          [&](std::int64_t i, std::int64_t j, std::int64_t wa, std::int64_t wb, std::int64_t wc) {
                            const std::size_t s = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * grid.nx;
                            if (seen[s] || std::isnan(grid.z[s])) return;
                            seen[s] = true;
                            const double plane = detail::plane_height(wa, wb, wc, z[0], z[1], z[2], area2);
                            const double e = std::abs(grid.z[s] - plane);
                            m.max = std::max(m.max, e);
                            sum2 += e * e;
                            ++m.samples;
                          });
  }
  for (std::size_t s = 0; s < seen.size(); ++s) m.uncovered += !seen[s] && !std::isnan(grid.z[s]);
  if (m.samples > 0) m.rms = std::sqrt(sum2 / static_cast<double>(m.samples));
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
