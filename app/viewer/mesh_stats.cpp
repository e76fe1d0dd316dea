#include "mesh_stats.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "meshstep/refine/quality.hpp"

namespace meshstep::viewer {

Stats measure(const scene::MeshLayer& mesh, const replay::LogReader* log) {
  Stats stats;
  std::vector<bool> used(mesh.points.size(), false);
  stats.min_angle = 180.0;
  for (const auto& t : mesh.triangles) {
    if (t[0] >= used.size() || t[1] >= used.size() || t[2] >= used.size()) continue;
    const auto q = quality::shape(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    const double smallest = q.min_angle_deg();
    stats.min_angle = std::min(stats.min_angle, smallest);
    stats.max_angle = std::max(stats.max_angle, q.max_angle_deg());
    const auto bin = static_cast<std::size_t>(std::clamp(smallest / 60.0 * 18.0, 0.0, 17.0));
    stats.histogram[bin] += 1.0f;
    for (const std::uint32_t v : t) used[v] = true;
  }
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
