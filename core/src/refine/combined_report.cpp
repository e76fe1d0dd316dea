// One report for a chain of refinements (refine.hpp: combined_report).
#include <string>

#include "meshstep/refine/refine.hpp"

namespace meshstep {

RefineReport combined_report(std::span<const RefineReport> reports) {
  if (reports.empty()) return {};
  RefineReport total = reports.front();
  for (std::size_t i = 1; i < reports.size(); ++i) {
    const RefineReport& step = reports[i];
    // What each operation did adds up.
    total.steiner_vertices += step.steiner_vertices;
    total.segment_splits += step.segment_splits;
    total.triangles_split += step.triangles_split;
    total.rejected_points += step.rejected_points;
    total.skipped_small_angle += step.skipped_small_angle;
    total.unsplittable_segments += step.unsplittable_segments;
    total.points_out_of_range += step.points_out_of_range;
    total.kept_segment_refusals += step.kept_segment_refusals;
    total.removed_vertices += step.removed_vertices;
    total.triangulate_ms += step.triangulate_ms;
    total.refine_ms += step.refine_ms;
    for (const auto& [name, ms] : step.phase_ms) total.phase_ms.emplace_back(std::to_string(i + 1) + ":" + name, ms);
    // What the mesh is like at the end is the last operation's word.
    total.stopped_by_cap = step.stopped_by_cap;
    total.below_min_angle = step.below_min_angle;
    total.bad_triangles = step.bad_triangles;
    total.bad_near_small_input_angle = step.bad_near_small_input_angle;
    total.bounds_met = step.bounds_met;
    total.region_triangles = step.region_triangles;
  }
  return total;
}

}  // namespace meshstep
