#include "mesh_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "meshstep/refine/quality.hpp"

namespace meshstep::viewer {

namespace {

constexpr std::size_t kBins = std::tuple_size_v<decltype(Stats::histogram)>;
constexpr double kBinDegrees = 60.0 / static_cast<double>(kBins);
static_assert(kBins == 18, "bin_of_degrees spells out 18 bins over 60 degrees");

// The histogram's bin of a smallest angle, as the statistics have always put it (this very
// expression: another rounding moves angles on an edge).
std::size_t bin_of_degrees(double smallest_deg) {
  return static_cast<std::size_t>(std::clamp(smallest_deg / 60.0 * 18.0, 0.0, 17.0));
}
double min_angle_deg(double sin2) { return quality::degrees(std::asin(std::min(1.0, std::sqrt(sin2)))); }

// The bins' lower edges as sin^2 of the angle: a smallest angle (at most 60 degrees, where
// sin^2 grows with the angle) is binned by comparing its sin^2 with them, with no asin and
// no square root per triangle. A value within a hair of an edge is binned as above instead,
// so that every triangle lands in the bin the trigonometry gives.
struct BinEdges {
  std::array<double, kBins> sin2{};  // [0] unused: the first bin has no lower edge
  BinEdges() {
    for (std::size_t k = 1; k < kBins; ++k) {
      const double s = std::sin(quality::radians(static_cast<double>(k) * kBinDegrees));
      sin2[k] = s * s;
    }
  }
  std::size_t bin(double s2) const {
    std::size_t b = 0;
    while (b + 1 < kBins && s2 >= sin2[b + 1]) ++b;
    constexpr double kHair = 1e-9;
    const bool near_lower = b > 0 && s2 - sin2[b] <= kHair * sin2[b];
    const bool near_upper = b + 1 < kBins && sin2[b + 1] - s2 <= kHair * sin2[b + 1];
    return near_lower || near_upper ? bin_of_degrees(min_angle_deg(s2)) : b;
  }
};

}  // namespace

// The scan of every triangle for each new moment (each picture of a run scrubbed): the
// extremes are found on sin^2 of the smallest angle and cos of the largest, which grow and
// shrink with the angles, and turned into degrees once; four runs side by side spent a
// third of their workers' time here with two inverse trigonometric functions a triangle.
Stats measure(const scene::MeshLayer& mesh, const replay::LogReader* log) {
  static const BinEdges edges;
  Stats stats;
  std::vector<bool> used(mesh.points.size(), false);
  double least_sin2 = std::numeric_limits<double>::infinity(), least_cos_max = 1.0;
  bool any = false;
  for (const auto& t : mesh.triangles) {
    if (t[0] >= used.size() || t[1] >= used.size() || t[2] >= used.size()) continue;
    const auto q = quality::shape(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    const double s2 = q.sin2_min_angle();
    least_sin2 = std::min(least_sin2, s2);
    least_cos_max = std::min(least_cos_max, q.cos_max_angle());
    any = true;
    stats.histogram[edges.bin(s2)] += 1.0f;
    for (const std::uint32_t v : t) used[v] = true;
  }
  // Monotone: the least sin^2 is the smallest angle's, the least cosine the largest's.
  stats.min_angle = any ? min_angle_deg(least_sin2) : 180.0;
  stats.max_angle = any ? quality::degrees(std::acos(std::clamp(least_cos_max, -1.0, 1.0))) : 0.0;
  stats.triangles = mesh.triangles.size();
  const std::uint64_t inputs =
      log ? log->run().input_vertices : used.size();
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) continue;
    ++stats.vertices;
    if (log && v < log->vertices().size()) stats.steiner += log->vertices()[v].input_index >= inputs;
  }
  if (stats.triangles == 0) stats.min_angle = 0.0;
  return stats;
}

}  // namespace meshstep::viewer
