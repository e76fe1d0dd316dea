// Scenes of a mesh alone and of an input alone, and the parts every scene shares: the
// segments, vertices, holes and regions over the mesh, and the bounds a camera fits.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "fill.hpp"
#include "parts.hpp"
#include "style.hpp"

namespace meshstep::scene {

namespace detail {

namespace {

// Region points get a world label each, up to this many (beyond, they would be clutter).
constexpr std::size_t kMaxRegionLabels = 64;

std::string count_text(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The box a circle may stretch the bounds to: the box of everything else grown by a tenth
// of its larger side on each side. A circle just beyond the mesh shows whole; a large one
// (the in-circle test of a nearly flat triangle, radius a thousand times the mesh) is cut
// at the picture's edge instead of shrinking the mesh to a dot.
BBox circle_limit(const BBox& b) {
  if (b.empty()) return b;
  const double grow = 0.1 * std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
  return {{b.lo.x - grow, b.lo.y - grow}, {b.hi.x + grow, b.hi.y + grow}};
}

}  // namespace

Scene start_scene(const SceneOptions& options) {
  Scene scene;
  scene.theme = options.theme;
  scene.background = base_style(options.theme).background;
  scene.caption_color = base_style(options.theme).text;
  scene.visible = options.layers;
  scene.text_scale = options.text_scale;
  const BaseStyle& base = base_style(options.theme);
  scene.mesh.edge_color = base.edge;
  scene.mesh.edge_width_px = base.edge_width_px;
  return scene;
}

double quality_bound(const SceneOptions& options, const replay::LogReader* log) {
  if (options.min_angle_bound > 0.0) return options.min_angle_bound;
  if (log) {
    const double run = log->run().min_angle.value_or(0.0);
    if (run > 0.0 && run < 60.0) return run;
  }
  return 30.0;
}

void add_segments(Scene& scene, std::span<const Point> points, std::span<const Segment> segments) {
  Shape s;
  s.layer = Layer::segments;
  s.kind = ShapeKind::lines;
  s.role = "segments";
  s.label = "segments (constrained edges)";
  s.color = base_style(scene.theme).segment;
  s.width_px = base_style(scene.theme).segment_width_px;
  s.points.reserve(2 * segments.size());
  for (const Segment& seg : segments)
    if (seg.a < points.size() && seg.b < points.size()) s.points.insert(s.points.end(), {points[seg.a], points[seg.b]});
  if (!s.points.empty()) scene.shapes.push_back(std::move(s));
}

void add_vertex_markers(Scene& scene, std::span<const Point> input, std::span<const Point> steiner,
                        const SceneOptions& options) {
  if (input.size() + steiner.size() > options.max_vertex_markers) return;
  const BaseStyle& base = base_style(scene.theme);
  const auto add = [&](const char* role, const char* label, Rgba fill, Marker marker, float px,
                       std::span<const Point> at) {
    if (at.empty()) return;
    Shape& s = scene.shapes.emplace_back();
    s.layer = Layer::vertices;
    s.kind = ShapeKind::markers;
    s.role = role;
    s.label = label;
    s.color = base.vertex_outline;
    s.fill = fill;
    s.width_px = 1.0f;
    s.marker = marker;
    s.marker_px = px;
    s.points.assign(at.begin(), at.end());
  };
  add("input_vertices", "input vertices", base.input_vertex, Marker::square, 7.0f, input);
  add("steiner_vertices", "Steiner vertices", base.steiner_vertex, Marker::disc, 7.0f, steiner);
}

void add_holes(Scene& scene, std::span<const Point> holes) {
  if (holes.empty()) return;
  Shape& s = scene.shapes.emplace_back();
  s.layer = Layer::holes;
  s.kind = ShapeKind::markers;
  s.role = "holes";
  s.label = "hole points";
  s.color = base_style(scene.theme).hole;
  s.width_px = 2.5f;
  s.marker = Marker::cross;
  s.marker_px = 12.0f;
  s.points.assign(holes.begin(), holes.end());
}

void add_regions(Scene& scene, std::span<const Region> regions) {
  if (regions.empty()) return;
  const BaseStyle& base = base_style(scene.theme);
  Shape& s = scene.shapes.emplace_back();
  s.layer = Layer::holes;
  s.kind = ShapeKind::markers;
  s.role = "regions";
  s.label = "region points";
  s.color = base.region_point;
  s.width_px = 2.5f;
  s.marker = Marker::diamond;
  s.marker_px = 11.0f;
  for (const Region& r : regions) s.points.push_back(r.point);
  if (regions.size() > kMaxRegionLabels) return;
  for (const Region& r : regions) {
    char text[64];
    if (r.max_area > 0.0)
      std::snprintf(text, sizeof text, "region %g, area \u2264 %g", r.attribute, r.max_area);
    else
      std::snprintf(text, sizeof text, "region %g", r.attribute);
    scene.labels.push_back({r.point, text, base.text, 12.0f, 9.0f, -9.0f, 1});
  }
}

BBox points_box(std::span<const Point> points) {
  BBox box;
  for (const Point& p : points) box.add(p);
  return box;
}

BBox scene_bounds(const Scene& scene, BBox box) {
  for (const Shape& s : scene.shapes)
    if (s.kind != ShapeKind::circles)
      for (const Point& p : s.points) box.add(p);
  const BBox limit = circle_limit(box);
  for (const Shape& s : scene.shapes) {
    if (s.kind != ShapeKind::circles) continue;
    for (std::size_t i = 0; i < s.points.size() && i < s.radii.size(); ++i) {
      const Point c = s.points[i];
      const double r = s.radii[i];
      Point lo{c.x - r, c.y - r}, hi{c.x + r, c.y + r};
      if (!limit.empty()) {
        lo = {std::max(lo.x, limit.lo.x), std::max(lo.y, limit.lo.y)};
        hi = {std::min(hi.x, limit.hi.x), std::min(hi.y, limit.hi.y)};
        if (lo.x > hi.x || lo.y > hi.y) continue;  // entirely beyond the limit
      }
      box.add(lo);
      box.add(hi);
    }
  }
  return box;
}

}  // namespace detail

Scene build_scene(const TriMesh& mesh, const SceneOptions& options) {
  Scene scene = detail::start_scene(options);
  scene.mesh.points = mesh.points;
  scene.mesh.triangles = mesh.triangles;
  detail::FillInput in;
  in.points = scene.mesh.points;
  in.triangles = scene.mesh.triangles;
  // The region attribute is a triangle's first attribute (copied out when there are more).
  const std::size_t per_triangle = mesh.attributes_per_triangle;
  if (per_triangle >= 1 && mesh.triangle_attributes.size() == mesh.triangles.size() * per_triangle) {
    scene.mesh.region.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      scene.mesh.region[t] = mesh.triangle_attributes[t * per_triangle];
    in.region = scene.mesh.region;
  }
  in.min_angle_bound = detail::quality_bound(options, nullptr);
  scene.legend = detail::fill_triangles(options.color_by, options.theme, in, scene.mesh);

  if (options.layers.has(Layer::voronoi)) detail::add_voronoi(scene, options);
  const std::span<const Point> points = mesh.points;
  const std::size_t input_count = std::min(mesh.input_vertex_count, points.size());
  detail::add_segments(scene, points, mesh.segments);
  detail::add_vertex_markers(scene, points.first(input_count), points.subspan(input_count), options);
  detail::add_holes(scene, mesh.holes);
  detail::add_regions(scene, mesh.regions);
  scene.caption = detail::count_text(mesh.triangles.size(), "triangle", "triangles") + ", " +
                  detail::count_text(mesh.points.size(), "vertex", "vertices");
  // Every point, used by a triangle or not (a duplicate, one outside the domain).
  scene.bounds = detail::scene_bounds(scene, detail::points_box(points));
  return scene;
}

Scene build_scene(const Pslg& input, const SceneOptions& options) {
  Scene scene = detail::start_scene(options);
  scene.mesh.points = input.points;  // no triangles: the points bound the picture
  detail::add_segments(scene, input.points, input.segments);
  detail::add_vertex_markers(scene, input.points, {}, options);
  detail::add_holes(scene, input.holes);
  detail::add_regions(scene, input.regions);
  std::string caption = "input: " + detail::count_text(input.points.size(), "vertex", "vertices") + ", " +
                        detail::count_text(input.segments.size(), "segment", "segments");
  if (!input.holes.empty()) caption += ", " + detail::count_text(input.holes.size(), "hole", "holes");
  if (!input.regions.empty()) caption += ", " + detail::count_text(input.regions.size(), "region", "regions");
  scene.caption = std::move(caption);
  scene.bounds = detail::scene_bounds(scene, detail::points_box(input.points));
  return scene;
}

}  // namespace meshstep::scene
