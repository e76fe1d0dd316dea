// The scene of one moment of a recorded run: the cursor's mesh, exactly, filled and with
// its segments and vertices, the faces the current step made highlighted, the step
// explained over it, and the caption.
//
// The mesh layer is read straight from the cursor's face slots, not through
// Replay::mesh(): that renumbers vertices in input order (sorting them) and collects the
// constrained edges in a map, several times the cost of the whole scene at a million faces.
// Here points are indexed by the log's vertex ids, the numbering the caption and
// `meshstep log dump` use, and triangles come in slot order, as Replay::mesh() lists them.
#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "fill.hpp"
#include "meshstep/error.hpp"
#include "parts.hpp"
#include "replay/regions.hpp"
#include "style.hpp"

namespace meshstep::scene {

namespace {

using replay::FaceRecord;

bool drawn(const FaceRecord& r) { return !r.dead() && !r.ghost(); }

// The mesh at the cursor, and what the rest of the scene needs to know about it.
struct MomentMesh {
  std::vector<FaceId> slot_of;                          // per triangle, its face slot (ascending)
  std::vector<Segment> segments;                        // constrained edges, once each
  std::vector<std::uint8_t> constrained_bits;            // per triangle, its slot's
  std::vector<Point> input_vertices, steiner_vertices;  // present at the cursor
  BBox box;                                             // of the vertices present
};

MomentMesh read_mesh(const replay::Replay& cursor, MeshLayer& layer) {
  const replay::LogReader& log = cursor.log();
  const std::vector<replay::VertexInfo>& vertices = log.vertices();
  const std::uint64_t position = cursor.position();
  MomentMesh out;

  layer.points.resize(vertices.size());
  const std::uint64_t input_count = log.run().input_vertices;
  for (VertexId v = 0; v < vertices.size(); ++v) {
    const replay::VertexInfo& info = vertices[v];
    layer.points[v] = info.point;
    // Present: introduced by now and not removed yet. A duplicate stands on its original.
    if (info.event == kNone || info.event >= position || info.removed < position) continue;
    out.box.add(info.point);
    if (info.same_as != kNone) continue;
    (info.input_index < input_count ? out.input_vertices : out.steiner_vertices).push_back(info.point);
  }

  const std::vector<FaceRecord>& slots = cursor.slots();
  std::vector<std::pair<VertexId, VertexId>> constrained;
  layer.triangles.clear();
  for (FaceId s = 0; s < slots.size(); ++s) {
    const FaceRecord& r = slots[s];
    if (!drawn(r)) continue;
    if (std::max({r.v[0], r.v[1], r.v[2]}) >= vertices.size())
      throw InputError(log.path(), 0, "face slot " + std::to_string(s) + " names a vertex the log never introduces");
    layer.triangles.push_back({r.v[0], r.v[1], r.v[2]});
    out.slot_of.push_back(s);
    out.constrained_bits.push_back(r.constrained);
    for (int i = 0; i < 3; ++i)
      if (r.constrained >> i & 1) constrained.push_back(std::minmax(r.v[i], r.v[(i + 1) % 3]));
  }
  // An interior segment is constrained in both its faces.
  std::sort(constrained.begin(), constrained.end());
  constrained.erase(std::unique(constrained.begin(), constrained.end()), constrained.end());
  for (const auto& [a, b] : constrained) out.segments.push_back({a, b, 1});
  return out;
}

void add_changed_faces(Scene& scene, const detail::StepStory& story, const std::vector<FaceRecord>& slots,
                       const std::vector<FaceId>& slot_of) {
  for (const FaceId slot : story.written) {
    if (slot >= slots.size() || !drawn(slots[slot])) continue;
    const auto it = std::lower_bound(slot_of.begin(), slot_of.end(), slot);
    scene.highlighted.push_back(static_cast<std::uint32_t>(it - slot_of.begin()));
  }
  if (scene.highlighted.empty()) return;
  Shape& s = scene.shapes.emplace_back();
  s.layer = Layer::highlight;
  s.kind = ShapeKind::triangles;
  s.role = "changed_faces";
  s.label = "faces the step made or changed";
  s.color = detail::overlay_style(scene.theme).changed.fill;
  for (const std::uint32_t t : scene.highlighted)
    for (const std::uint32_t v : scene.mesh.triangles[t]) s.points.push_back(scene.mesh.points[v]);
}

}  // namespace

Scene build_scene(const replay::Replay& cursor, const SceneOptions& options, const FaceAges* ages) {
  const replay::LogReader& log = cursor.log();
  if (ages && !ages->current(cursor))
    throw std::logic_error("build_scene: the face ages were not updated to the cursor (FaceAges::update)");
  Scene scene = detail::start_scene(options);
  const MomentMesh mesh = read_mesh(cursor, scene.mesh);
  const detail::StepStory story = detail::read_step(cursor);

  detail::FillInput in;
  in.points = scene.mesh.points;
  in.triangles = scene.mesh.triangles;
  in.min_angle_bound = detail::quality_bound(options, &log);
  std::vector<std::uint64_t> triangle_ages;
  if (ages && options.color_by == ColorBy::age) {
    triangle_ages.resize(mesh.slot_of.size());
    for (std::size_t t = 0; t < mesh.slot_of.size(); ++t) triangle_ages[t] = ages->age(mesh.slot_of[t]);
    in.ages = triangle_ages;
    in.current_step = story.in_step ? story.step : 0;
  }
  std::vector<double> heights;  // by vertex id, as the points are
  if (options.color_by == ColorBy::height && log.has_elevation()) {
    heights.reserve(scene.mesh.points.size());
    for (const replay::VertexInfo& v : log.vertices()) heights.push_back(v.z);
    in.heights = heights;
  }
  const std::vector<Region>& regions = log.header().regions;
  if (!regions.empty()) {
    scene.mesh.region = replay::detail::region_attributes(scene.mesh.points, scene.mesh.triangles, mesh.constrained_bits, regions);
    in.region = scene.mesh.region;
  }
  scene.legend = detail::fill_triangles(options.color_by, options.theme, in, scene.mesh);

  if (options.layers.has(Layer::voronoi)) detail::add_voronoi(scene, options);
  add_changed_faces(scene, story, cursor.slots(), mesh.slot_of);
  detail::add_overlays(scene, story, log);
  // Before the first triangle the mesh has nothing to show: the input stands in for it, all
  // of it, whichever of its vertices the preamble has introduced so far.
  const bool before_first_triangle = scene.mesh.triangles.empty();
  BBox box = mesh.box;
  if (before_first_triangle) {
    const BBox input = detail::add_input_moment(scene, log, options);
    if (!input.empty()) box.add(input.lo), box.add(input.hi);
  } else {
    detail::add_segments(scene, scene.mesh.points, mesh.segments);
    detail::add_vertex_markers(scene, mesh.input_vertices, mesh.steiner_vertices, options);
  }
  detail::add_regions(scene, regions);
  detail::add_refine_region(scene, log, cursor.position());
  scene.caption = detail::step_caption(story, log);
  if (before_first_triangle && !story.in_step) scene.caption += " \u00B7 " + detail::input_description(log);
  scene.bounds = detail::scene_bounds(scene, box);
  return scene;
}

}  // namespace meshstep::scene
