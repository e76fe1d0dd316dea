// The region a refinement is limited to, drawn as a dashed outline (parts.hpp): what a
// student needs to see to understand why one part of the mesh is finer than the rest.
#include <optional>

#include "meshstep/error.hpp"
#include "meshstep/replay/operations.hpp"
#include "parts.hpp"
#include "style.hpp"

namespace meshstep::scene::detail {
namespace {

// The region of the operation whose phase holds `position` (a recipe's log), or the run's
// own (--region on a run of one operation: all the way through, the triangulation included).
std::optional<RefineRegion> region_at(const replay::LogReader& log, std::uint64_t position) {
  if (log.run().operations.empty()) return log.run().region;
  const replay::PhaseSpan* at = nullptr;
  for (const replay::PhaseSpan& span : log.phases()) {
    if (span.begin >= position) break;
    at = &span;
  }
  const Operation* op = at ? replay::operation_of(log, *at) : nullptr;
  if (!op) return std::nullopt;
  try {
    return region_of(*op);
  } catch (const InputError&) {
    return std::nullopt;  // a --region-poly file that is gone since: the picture goes without
  }
}

}  // namespace

void add_refine_region(Scene& scene, const replay::LogReader& log, std::uint64_t position) {
  const std::optional<RefineRegion> region = region_at(log, position);
  if (!region) return;
  Shape& s = scene.shapes.emplace_back();
  s.layer = Layer::holes;  // with the input's other marks: hole and region points
  s.kind = ShapeKind::lines;
  s.role = "refine_region";
  s.label = "refinement region";
  s.color = base_style(scene.theme).region_point;
  s.width_px = 2.0f;
  s.dashed = true;
  const std::vector<Point>& corners = region->vertices();
  for (std::size_t i = 0; i < corners.size(); ++i) {
    s.points.push_back(corners[i]);
    s.points.push_back(corners[(i + 1) % corners.size()]);
  }
}

}  // namespace meshstep::scene::detail
