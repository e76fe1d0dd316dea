// Golden-image tests: a dozen small pictures of the teaching example, one for every overlay
// type and every colour map, each drawn off screen on every backend (EGL, OSMesa) and
// compared with a PNG in tests/golden/.
//
// Each case checks its scene exactly first (where the circle is, which faces are
// highlighted, which value each colour stands for), computed independently from the log;
// then the picture, with a tolerance: a channel may differ by 5, on at most 0.1% of the
// pixels (llvmpipe's output is exact run to run on one machine, but may round differently
// on another CPU). On failure the actual picture and a diff picture are written to
// build/tests/render/golden-failures/.
//
// To change the goldens on purpose (a new colour, a new layout), run
//   MESHSTEP_UPDATE_GOLDENS=1 build/tests/render/meshstep_golden_tests
// look at every changed PNG in tests/golden/ (git diff shows which), and commit them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "golden_runs.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/image.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/scene/lift.hpp"
#include "meshstep/scene/surface_view.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"

namespace meshstep::golden {
namespace {

namespace fs = std::filesystem;
using replay::Event;
using replay::EventType;
using scene::Scene;

constexpr int kWidth = 640, kHeight = 400;
constexpr int kTolerance = 5;                // per channel
constexpr double kMaxDifferingShare = 0.001;  // of the pixels

// ---------------------------------------------------------------------------------------
// Scene facts computed independently of the scene builder.

Point vertex(const replay::LogReader& log, std::uint32_t id) { return log.vertices().at(id).point; }

Point circumcenter(const Point& a, const Point& b, const Point& c) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double d = 2.0 * (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

double distance(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

const scene::Shape& shape(const Scene& s, const char* role) {
  const scene::Shape* found = s.find(role);
  if (!found) throw std::runtime_error(std::string("the scene has no shape '") + role + "'");
  return *found;
}

// The points of every shape with this role (a role may have several shapes: the latest
// flip emphasised, the earlier ones faded).
std::vector<Point> all_points(const Scene& s, const char* role) {
  std::vector<Point> out;
  for (const scene::Shape& shape : s.shapes)
    if (shape.role == role) out.insert(out.end(), shape.points.begin(), shape.points.end());
  return out;
}

void expect_point(const Point& actual, const Point& expected, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
}

// The scene of the run at the moment just after the first step with a wanted event.
struct Moment {
  const replay::LogReader* log = nullptr;
  std::uint64_t position = 0;
  Event event;  // the wanted event (spans not kept)
  std::uint64_t event_index = 0;
};

std::optional<Moment> moment(const std::string& run, const std::function<bool(const Event&)>& wanted) {
  const replay::LogReader* log = lesson_run(run);
  if (!log) return std::nullopt;
  for (std::uint64_t e = 0; e < log->event_count(); ++e) {
    const Event ev = log->event(e);
    if (!wanted(ev)) continue;
    const std::uint64_t step = log->step_of_event(e);
    Moment m{log, step < log->step_count() ? log->step_start(step + 1) : e + 1, ev, e};
    m.event.list = {};
    m.event.points = {};
    m.event.writes = {};
    return m;
  }
  ADD_FAILURE() << "no such event in the run '" << run << "'";
  return std::nullopt;
}

Scene scene_at(const Moment& m, const scene::SceneOptions& options = {}) {
  replay::Replay cursor(*m.log);
  cursor.seek_event(m.position);
  if (options.color_by != scene::ColorBy::age) return scene::build_scene(cursor, options);
  scene::FaceAges ages;
  ages.update(cursor);
  return scene::build_scene(cursor, options, &ages);
}

// ---------------------------------------------------------------------------------------
// The cases: each makes its scene and checks it exactly.

struct GoldenCase {
  const char* name;
  // Builds the scene and checks it; returns nullopt (after reporting why) when it cannot.
  std::function<std::optional<Scene>()> make;
};

constexpr const char* kOffcenter = "--algorithm offcenter --min-angle 30";

std::optional<Scene> input_case() {
  const Pslg input = io::read_pslg(asset("lesson.poly"));
  const Scene s = scene::build_scene(input, {});
  EXPECT_TRUE(s.mesh.triangles.empty());
  EXPECT_EQ(shape(s, "segments").points.size(), 2 * input.segments.size());
  const scene::Shape& holes = shape(s, "holes");
  EXPECT_EQ(holes.points.size(), 1u);
  expect_point(holes.points.at(0), {3.5, 3.5});
  return s;
}

std::optional<Scene> insertion_case() {
  // A vertex inserted with Lawson flips: every face the step leaves is one round the new
  // vertex, so the highlighted faces are exactly its star.
  const auto m = moment(kOffcenter, [](const Event& e) {
    return e.type == EventType::flip && e.code == static_cast<std::uint8_t>(replay::FlipReason::delaunay);
  });
  if (!m) return std::nullopt;
  const Scene s = scene_at(*m);
  const Point p = vertex(*m->log, m->event.ids[2]);  // c: the new vertex, opposite a-b
  std::size_t star = 0;
  for (const auto& t : s.mesh.triangles)
    for (const std::uint32_t v : t) star += s.mesh.points[v] == p;
  EXPECT_EQ(s.highlighted.size(), star);
  for (const std::uint32_t f : s.highlighted) {
    const auto& t = s.mesh.triangles.at(f);
    EXPECT_TRUE(s.mesh.points[t[0]] == p || s.mesh.points[t[1]] == p || s.mesh.points[t[2]] == p);
  }
  shape(s, "located_triangle");
  // Every flip circle passes through a, b, c of its flip and has d inside.
  const scene::Shape& circles = shape(s, "flip_circle");
  EXPECT_FALSE(circles.points.empty());
  EXPECT_EQ(circles.points.size(), circles.radii.size());
  const Point a = vertex(*m->log, m->event.ids[0]), b = vertex(*m->log, m->event.ids[1]);
  const Point o = circumcenter(a, b, p);
  const bool found = std::any_of(circles.points.begin(), circles.points.end(),
                                 [&](const Point& c) { return distance(c, o) < 1e-9; });
  EXPECT_TRUE(found) << "no flip circle round the first flip's triangle";
  return s;
}

std::optional<Scene> segment_recovery_case() {
  const auto m = moment(kOffcenter, [](const Event& e) {
    return e.type == EventType::flip && e.code == static_cast<std::uint8_t>(replay::FlipReason::segment_recovery);
  });
  if (!m) return std::nullopt;
  const Scene s = scene_at(*m);
  const scene::Shape& before = shape(s, "flip_before");
  const scene::Shape& after = shape(s, "flip_after");
  EXPECT_GE(before.points.size(), 2u);
  EXPECT_GE(after.points.size(), 2u);
  expect_point(before.points.at(0), vertex(*m->log, m->event.ids[0]));
  expect_point(before.points.at(1), vertex(*m->log, m->event.ids[1]));
  expect_point(after.points.at(0), vertex(*m->log, m->event.ids[2]));
  expect_point(after.points.at(1), vertex(*m->log, m->event.ids[3]));
  return s;
}

std::optional<Scene> encroached_case(const std::string& run, bool lens) {
  const auto m = moment(run, [](const Event& e) { return e.type == EventType::encroached; });
  if (!m) return std::nullopt;
  const Scene s = scene_at(*m);
  const Point a = vertex(*m->log, m->event.ids[0]), b = vertex(*m->log, m->event.ids[1]);
  if (lens) {
    EXPECT_EQ(s.find("diametral_circle"), nullptr);
    EXPECT_FALSE(shape(s, "diametral_lens").points.empty());
  } else {
    const scene::Shape& circle = shape(s, "diametral_circle");
    EXPECT_EQ(circle.points.size(), 1u);
    expect_point(circle.points.at(0), {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}, 1e-12);
    EXPECT_NEAR(circle.radii.at(0), 0.5 * distance(a, b), 1e-12);
  }
  expect_point(shape(s, "encroaching_point").points.at(0), m->event.point);
  // The split point lies on the subsegment, strictly between its ends.
  const Point p = shape(s, "split_point").points.at(0);
  EXPECT_NEAR(distance(a, p) + distance(p, b), distance(a, b), 1e-9 * distance(a, b));
  EXPECT_GT(distance(a, p), 0.0);
  EXPECT_GT(distance(b, p), 0.0);
  return s;
}

std::optional<Scene> offcenter_case() {
  // A refinement step whose selection considered two points (the off-center was chosen
  // over the circumcenter, or the other way round).
  const auto m = moment(kOffcenter, [](const Event& e) {
    return e.type == EventType::point_selected && !e.points.empty();
  });
  if (!m) return std::nullopt;
  const Scene s = scene_at(*m);
  const Point a = vertex(*m->log, m->event.ids[0]), b = vertex(*m->log, m->event.ids[1]),
              c = vertex(*m->log, m->event.ids[2]);
  const scene::Shape& bad = shape(s, "bad_triangle");
  EXPECT_EQ(bad.points.size(), 3u);
  expect_point(bad.points.at(0), a);
  expect_point(bad.points.at(1), b);
  expect_point(bad.points.at(2), c);
  expect_point(shape(s, "selected_point").points.at(0), m->event.point);
  const scene::Shape& circle = shape(s, "circumcircle");
  expect_point(circle.points.at(0), circumcenter(a, b, c), 1e-9);
  EXPECT_NEAR(circle.radii.at(0), distance(circumcenter(a, b, c), a), 1e-9);
  EXPECT_FALSE(shape(s, "alternative_points").points.empty());
  // The criterion the bad triangle failed: its smallest angle, below the bound.
  shape(s, "failed_criterion");
  EXPECT_LT(triangle_min_angle_deg(a, b, c), 30.0);
  return s;
}

std::optional<Scene> cavity_case() {
  // A cavity of three faces or more (the first ones, round the first triangle, are mostly
  // ghost faces outside the domain).
  const auto m = moment("--algorithm circumcenter --insertion cavity --min-angle 30", [](const Event& e) {
    return e.type == EventType::cavity &&
           std::count_if(e.writes.begin(), e.writes.end(), [](const replay::SlotWrite& w) {
             return !w.before.dead() && !w.before.ghost();
           }) >= 3;
  });
  if (!m) return std::nullopt;
  const Scene s = scene_at(*m);
  std::size_t removed = 0, made = 0;
  for (const replay::SlotWrite& w : m->log->writes(m->event_index)) {
    removed += !w.before.dead() && !w.before.ghost();
    made += !w.after.dead() && !w.after.ghost();
  }
  EXPECT_EQ(shape(s, "cavity").points.size(), 3 * removed);
  EXPECT_EQ(shape(s, "new_fan").points.size(), 3 * made);
  EXPECT_EQ(shape(s, "cavity_boundary").points.size(), 2 * made);
  return s;
}

std::optional<Scene> lepp_case() {
  const auto m = moment("--algorithm lepp-centroid --min-angle 30", [](const Event& e) {
    return e.type == EventType::lepp_path && e.list.size() >= 9;  // three triangles or more
  });
  if (!m) return std::nullopt;
  const Scene s = scene_at(*m);
  // The path's triangles in order: longest edges grow along it.
  const scene::Shape& path = shape(s, "lepp_path");
  EXPECT_GE(path.points.size(), 9u);
  EXPECT_EQ(path.points.size() % 3, 0u);
  double last = 0.0;
  for (std::size_t i = 0; i < path.points.size(); i += 3) {
    const double longest = std::max({distance(path.points[i], path.points[i + 1]),
                                     distance(path.points[i + 1], path.points[i + 2]),
                                     distance(path.points[i + 2], path.points[i])});
    EXPECT_GE(longest, last);
    last = longest;
  }
  const scene::Shape& terminal = shape(s, "terminal_edge");
  const Point a = vertex(*m->log, m->event.ids[0]), b = vertex(*m->log, m->event.ids[1]);
  EXPECT_EQ(terminal.points.size(), 2u);
  EXPECT_TRUE((terminal.points.at(0) == a && terminal.points.at(1) == b) ||
              (terminal.points.at(0) == b && terminal.points.at(1) == a));
  EXPECT_NEAR(distance(a, b), last, 1e-12);
  return s;
}

std::optional<Scene> bisection_case() {
  const auto m = moment("--algorithm lepp-bisection --max-area 1.5", [](const Event& e) {
    return e.type == EventType::split_edge && e.code == static_cast<std::uint8_t>(replay::SplitReason::bisection);
  });
  if (!m) return std::nullopt;
  const Scene s = scene_at(*m);
  const Point a = vertex(*m->log, m->event.ids[1]), b = vertex(*m->log, m->event.ids[2]);
  const Point mid = vertex(*m->log, m->event.ids[0]);
  EXPECT_NEAR(distance(a, mid) + distance(mid, b), distance(a, b), 1e-9);
  const std::vector<Point> bisection = all_points(s, "bisection");
  const bool from_midpoint = std::any_of(bisection.begin(), bisection.end(), [&](const Point& p) { return p == mid; });
  const bool old_edge = std::any_of(bisection.begin(), bisection.end(), [&](const Point& p) { return p == a; });
  EXPECT_TRUE(from_midpoint);
  EXPECT_TRUE(old_edge);
  return s;
}

std::optional<Scene> removed_vertex_case() {
  const auto m = moment("--algorithm improve --min-angle 30 --max-area 1", [](const Event& e) {
    return e.type == EventType::remove_vertex;
  });
  if (!m) return std::nullopt;
  const Scene s = scene_at(*m);
  expect_point(shape(s, "removed_vertex").points.at(0), vertex(*m->log, m->event.ids[0]));
  EXPECT_GE(shape(s, "star").points.size(), 9u);  // three faces or more
  return s;
}

std::optional<Scene> end_of_run(const std::string& run, scene::ColorBy by, scene::Theme theme) {
  const replay::LogReader* log = lesson_run(run);
  if (!log) return std::nullopt;
  scene::SceneOptions options;
  options.color_by = by;
  options.theme = theme;
  return scene_at(Moment{log, log->event_count(), {}, 0}, options);
}

std::optional<Scene> angle_case() {
  auto s = end_of_run(kOffcenter, scene::ColorBy::angle, scene::Theme::light);
  if (!s) return s;
  EXPECT_EQ(s->mesh.fill.size(), s->mesh.triangles.size());
  EXPECT_EQ(s->mesh.values.size(), s->mesh.triangles.size());
  for (std::size_t i = 0; i < s->mesh.triangles.size(); ++i) {
    const auto& t = s->mesh.triangles[i];
    EXPECT_NEAR(s->mesh.values[i],
                triangle_min_angle_deg(s->mesh.points[t[0]], s->mesh.points[t[1]], s->mesh.points[t[2]]), 1e-9);
  }
  EXPECT_TRUE(s->legend.has_value());
  return s;
}

std::optional<Scene> quality_dark_case() {
  auto s = end_of_run("--algorithm lepp-centroid --min-angle 30", scene::ColorBy::quality, scene::Theme::dark);
  if (!s) return s;
  EXPECT_LT((s->background.r + s->background.g + s->background.b) / 3, 60);
  EXPECT_TRUE(s->legend.has_value());
  // Triangles on either side of the bound get colours of different hue families.
  return s;
}

std::optional<Scene> area_case() {
  auto s = end_of_run("--algorithm circumcenter --min-angle 25 --max-area 0.5", scene::ColorBy::area,
                      scene::Theme::light);
  if (!s) return s;
  EXPECT_EQ(s->mesh.values.size(), s->mesh.triangles.size());
  for (std::size_t i = 0; i < s->mesh.triangles.size(); ++i) {
    const auto& t = s->mesh.triangles[i];
    const Point& a = s->mesh.points[t[0]];
    const Point& b = s->mesh.points[t[1]];
    const Point& c = s->mesh.points[t[2]];
    EXPECT_NEAR(s->mesh.values[i], 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)), 1e-12);
  }
  return s;
}

std::optional<Scene> age_case() {
  auto s = end_of_run(kOffcenter, scene::ColorBy::age, scene::Theme::light);
  if (!s) return s;
  EXPECT_EQ(s->mesh.values.size(), s->mesh.triangles.size());
  // The faces the last step made are the youngest.
  const double youngest = *std::max_element(s->mesh.values.begin(), s->mesh.values.end());
  EXPECT_FALSE(s->highlighted.empty());
  for (const std::uint32_t f : s->highlighted) EXPECT_EQ(s->mesh.values.at(f), youngest);
  return s;
}

std::optional<Scene> region_case() {
  // The refined mesh with two regions, told apart by which side of x = 7.5 a triangle's
  // centroid is on.
  const replay::LogReader* log = lesson_run(kOffcenter);
  if (!log) return std::nullopt;
  replay::Replay cursor(*log);
  cursor.seek_event(log->event_count());
  TriMesh mesh = cursor.mesh();
  mesh.attributes_per_triangle = 1;
  for (const auto& t : mesh.triangles)
    mesh.triangle_attributes.push_back(
        (mesh.points[t[0]].x + mesh.points[t[1]].x + mesh.points[t[2]].x) / 3.0 < 7.5 ? 1.0 : 2.0);
  scene::SceneOptions options;
  options.color_by = scene::ColorBy::region;
  Scene s = scene::build_scene(mesh, options);
  EXPECT_TRUE(s.legend && s.legend->categorical);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (std::size_t j = 0; j < mesh.triangles.size(); ++j)
      EXPECT_EQ(s.mesh.fill[i] == s.mesh.fill[j], mesh.triangle_attributes[i] == mesh.triangle_attributes[j]);
  return s;
}

// Step 0 of the recorded run: the input before the first triangle, its vertices named by
// their numbers in lesson.poly.
std::optional<Scene> step_zero_case() {
  const replay::LogReader* log = lesson_run(kOffcenter);
  if (!log) return std::nullopt;
  const Pslg input = io::read_pslg(asset("lesson.poly"));
  const Scene s = scene_at(Moment{log, log->step_start(0), {}, 0});
  EXPECT_TRUE(s.mesh.triangles.empty());
  EXPECT_EQ(shape(s, "input_vertices").points, input.points);
  EXPECT_EQ(shape(s, "segments").points.size(), 2 * input.segments.size());
  EXPECT_EQ(shape(s, "holes").points, input.holes);
  EXPECT_EQ(s.labels.size(), input.points.size());
  return s;
}

// A small Delaunay triangulation with its Voronoi diagram, as a textbook draws the two:
// twelve points, the diagram's vertices the triangles' circumcenters (computed here).
std::optional<Scene> voronoi_case() {
  Pslg points;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {0.0, 0.0}, {4.0, 1.5}, {8.5, 0.0}, {1.5, 3.0}, {5.5, 2.5}, {9.0, 3.5},
           {0.5, 6.5}, {3.5, 5.0}, {7.0, 6.0}, {2.5, 8.5}, {6.0, 9.0}, {9.5, 8.0}})
    points.points.push_back({x, y});
  const TriMesh mesh = triangulate(points);
  scene::SceneOptions options;
  options.layers.set(scene::Layer::voronoi);
  const Scene s = scene::build_scene(mesh, options);
  const scene::Shape& centers = shape(s, "voronoi_vertices");
  // Every circumcenter within the picture's box is marked (a flat hull triangle's lies far
  // below it), and every mark is a circumcenter.
  std::size_t inside = 0;
  for (const auto& t : mesh.triangles) {
    const Point o = circumcenter(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    if (o.x < s.bounds.lo.x || o.x > s.bounds.hi.x || o.y < s.bounds.lo.y || o.y > s.bounds.hi.y) continue;
    ++inside;
    EXPECT_TRUE(std::any_of(centers.points.begin(), centers.points.end(), [&](const Point& c) { return distance(c, o) < 1e-9; }));
  }
  EXPECT_EQ(centers.points.size(), inside);
  EXPECT_GE(inside, mesh.triangles.size() - 2);
  EXPECT_FALSE(shape(s, "voronoi_edges").points.empty());
  EXPECT_FALSE(shape(s, "voronoi_rays").points.empty());
  EXPECT_EQ(shape(s, "voronoi_sites").points.size(), points.points.size());
  return s;
}

// A Gaussian hill on a 9x9 grid over [-4, 4]^2, each cell cut along its diagonal, seen from
// the default orbit camera with heights doubled.
std::optional<Scene> surface_hill_case() {
  io::Surface hill;
  constexpr int kN = 9;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const double x = i - 4.0, y = j - 4.0;
      hill.vertices.push_back({x, y, 2.0 * std::exp(-(x * x + y * y) / 6.0)});
    }
  for (std::uint32_t j = 0; j + 1 < kN; ++j)
    for (std::uint32_t i = 0; i + 1 < kN; ++i) {
      const std::uint32_t a = j * kN + i, b = a + 1, c = a + kN, d = c + 1;
      hill.triangles.push_back({a, b, d});
      hill.triangles.push_back({a, d, c});
    }
  scene::SurfaceView view;
  view.z_scale = 2.0;
  Scene s = scene::surface_scene(hill, view, scene::Theme::light, "hill");
  // Independently: the orthographic projection onto the plane of the default camera
  // (azimuth -60, elevation 35), and the depth toward the camera.
  const double a = -60.0 * std::numbers::pi / 180.0, e = 35.0 * std::numbers::pi / 180.0;
  const auto project = [&](const Point3& p) {
    const double z = 2.0 * p.z;
    return Point{-std::sin(a) * p.x + std::cos(a) * p.y,
                 -std::sin(e) * std::cos(a) * p.x - std::sin(e) * std::sin(a) * p.y + std::cos(e) * z};
  };
  const auto depth = [&](const Point3& p) {
    return std::cos(e) * std::cos(a) * p.x + std::cos(e) * std::sin(a) * p.y + std::sin(e) * 2.0 * p.z;
  };
  EXPECT_EQ(s.mesh.points.size(), hill.vertices.size());
  for (std::size_t i = 0; i < hill.vertices.size() && i < s.mesh.points.size(); ++i)
    expect_point(s.mesh.points[i], project(hill.vertices[i]), 1e-12);
  EXPECT_EQ(s.mesh.triangles.size(), hill.triangles.size());
  EXPECT_TRUE(s.mesh.painter_order);
  double previous = -INFINITY;
  for (std::size_t i = 0; i < s.mesh.triangles.size(); ++i) {
    const auto& t = s.mesh.triangles[i];
    const Point3 &p = hill.vertices[t[0]], &q = hill.vertices[t[1]], &r = hill.vertices[t[2]];
    const double d = (depth(p) + depth(q) + depth(r)) / 3.0;
    EXPECT_GE(d, previous - 1e-12) << "triangle " << i << " is nearer than the one after it";
    previous = d;
    EXPECT_NEAR(s.mesh.values.at(i), (p.z + q.z + r.z) / 3.0, 1e-12);
  }
  EXPECT_TRUE(s.legend && s.legend->title == "height");
  // The legend spans the lowest to the highest vertex: 2 exp(-32/6) = 0.0097 at the corners.
  if (s.legend) {
    EXPECT_EQ(s.legend->ticks.front().text, "0.01");
    EXPECT_EQ(s.legend->ticks.back().text, "2");
  }
  EXPECT_EQ(s.caption, "hill \u00B7 81 vertices, 128 triangles \u00B7 azimuth -60\u00B0, elevation 35\u00B0 \u00B7 heights \u00D72");
  return s;
}

// A terrain run's step in 3D: the worst triangle, its Lepp path and the sample that goes
// in next, lifted onto the surface (scene/lift.hpp), the camera turning about the middle.
std::optional<Scene> terrain_step_3d_case() {
  const replay::LogReader* log = golden::terrain_run("--max-error 1 --algorithm lepp-surface");
  if (!log) return std::nullopt;
  // The first refine step whose Lepp path has three triangles or more.
  std::optional<std::uint64_t> step;
  for (std::uint64_t k = 0; k < log->step_count() && !step; ++k)
    for (std::uint64_t e = log->step_start(k); e < log->step_start(k + 1); ++e) {
      const Event ev = log->event(e);
      if (ev.type == EventType::lepp_path && ev.list.size() >= 9 && log->step_start(k) > 40) {
        step = k;
        break;
      }
    }
  if (!step) {
    ADD_FAILURE() << "no step with a Lepp path of three triangles";
    return std::nullopt;
  }
  replay::Replay cursor(*log);
  cursor.seek_step(*step + 1);
  const Scene planar = scene::build_scene(cursor, scene::SceneOptions{});
  scene::SurfaceView view;
  view.azimuth_deg = -70.0;
  view.elevation_deg = 40.0;
  view.z_scale = 2.0;
  view.pivot = {235.0, 175.0, 125.0};  // the middle of the 470 m x 350 m grid
  const Scene s = scene::lift_scene(planar, scene::mesh_point_heights(planar, *log), view);
  // Each corner of the worst triangle and of the path is a vertex: it goes to the projection of
  // its position at its own height, about the pivot.
  const auto z_of = [&](const Point& p) {
    for (const replay::VertexInfo& v : log->vertices())
      if (v.event != kNone && v.point == p) return v.z;
    ADD_FAILURE() << "no vertex at (" << p.x << ", " << p.y << ")";
    return 0.0;
  };
  const double a = -70.0 * std::numbers::pi / 180.0, e = 40.0 * std::numbers::pi / 180.0;
  const auto projected = [&](const Point& p) {
    const double x = p.x - 235.0, y = p.y - 175.0, z = 2.0 * (z_of(p) - 125.0);
    return Point{-std::sin(a) * x + std::cos(a) * y, -std::sin(e) * std::cos(a) * x - std::sin(e) * std::sin(a) * y + std::cos(e) * z};
  };
  for (const char* role : {"bad_triangle", "lepp_path", "terminal_edge", "selected_point"}) {
    const scene::Shape& flat = shape(planar, role);
    const scene::Shape& lifted = shape(s, role);
    EXPECT_EQ(lifted.points.size(), flat.points.size()) << role;
    std::multiset<std::pair<double, double>> want, got;
    for (const Point& p : flat.points) {
      const Point q = projected(p);
      want.insert({std::round(q.x * 1e9), std::round(q.y * 1e9)});
    }
    for (const Point& p : lifted.points) got.insert({std::round(p.x * 1e9), std::round(p.y * 1e9)});
    EXPECT_EQ(got, want) << role;
  }
  EXPECT_EQ(s.find("circumcircle"), nullptr);
  EXPECT_TRUE(s.mesh.painter_order);
  EXPECT_TRUE(s.legend && s.legend->title == "height");
  EXPECT_NE(s.caption.find("vertical error"), std::string::npos) << s.caption;
  EXPECT_NE(s.caption.find("\u00B7 3D -70\u00B0, 40\u00B0, heights \u00D72"), std::string::npos) << s.caption;
  return s;
}

const std::vector<GoldenCase>& cases() {
  static const std::vector<GoldenCase> list = {
      {"input", input_case},
      {"step_zero", step_zero_case},
      {"voronoi", voronoi_case},
      {"insertion_flips", insertion_case},
      {"segment_recovery", segment_recovery_case},
      {"encroached_circle", [] { return encroached_case(kOffcenter + std::string(" --encroachment circle"), false); }},
      {"encroached_lens", [] { return encroached_case("--algorithm offcenter --min-angle 30 --encroachment lens", true); }},
      {"offcenter_selection", offcenter_case},
      {"cavity", cavity_case},
      {"lepp_path", lepp_case},
      {"bisection", bisection_case},
      {"removed_vertex", removed_vertex_case},
      {"color_angle", angle_case},
      {"color_quality_dark", quality_dark_case},
      {"color_area", area_case},
      {"color_age", age_case},
      {"color_region", region_case},
      {"surface_hill", surface_hill_case},
      {"terrain_step_3d", terrain_step_3d_case},
  };
  return list;
}

// ---------------------------------------------------------------------------------------
// Drawing and comparing.

class GoldenTest : public ::testing::TestWithParam<std::tuple<render::Backend, std::size_t>> {
 protected:
  void SetUp() override {
    try {
      context_ = render::make_offscreen_context(std::get<0>(GetParam()));
      renderer_ = std::make_unique<render::Renderer>();
    } catch (const render::GlUnavailable& e) {
      GTEST_SKIP() << "no OpenGL here: " << e.what();
    }
  }
  void TearDown() override {
    renderer_.reset();
    context_.reset();
  }

  scene::Image draw(const Scene& s, const scene::Camera& camera) {
    renderer_->render(s, camera, 4);
    return renderer_->read_pixels();
  }

  std::unique_ptr<render::GlContext> context_;
  std::unique_ptr<render::Renderer> renderer_;
};

bool updating() {
  const char* v = std::getenv("MESHSTEP_UPDATE_GOLDENS");
  return v && *v && std::string(v) != "0";
}

struct Verdict {
  bool same = false;
  std::string why;
  scene::ImageDiff diff;
};

Verdict compare_with(const scene::Image& expected, const scene::Image& actual) {
  Verdict v;
  v.diff = scene::compare_images(expected, actual, kTolerance);
  const double allowed = kMaxDifferingShare * expected.width * expected.height;
  v.same = v.diff.same_size && static_cast<double>(v.diff.differing_pixels) <= allowed;
  if (!v.diff.same_size)
    v.why = "size " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + " instead of " +
            std::to_string(expected.width) + "x" + std::to_string(expected.height);
  else
    v.why = std::to_string(v.diff.differing_pixels) + " pixels differ by more than " + std::to_string(kTolerance) +
            " (at most " + std::to_string(static_cast<int>(allowed)) + " may), largest difference " +
            std::to_string(v.diff.max_channel_delta);
  return v;
}

void expect_golden(const scene::Image& actual, const std::string& name, const std::string& backend) {
  const fs::path golden = fs::path(MESHSTEP_GOLDEN_DIR) / (name + ".png");
  if (updating()) {
    scene::write_png(golden.string(), actual, 9);
    std::printf("updated %s\n", golden.c_str());
    return;
  }
  if (!fs::exists(golden)) {
    ADD_FAILURE() << golden << " is missing: run with MESHSTEP_UPDATE_GOLDENS=1 to make it, and look at it";
    return;
  }
  const Verdict v = compare_with(scene::read_png(golden.string()), actual);
  if (v.same) return;
  const fs::path out = fs::path(MESHSTEP_GOLDEN_OUT);
  fs::create_directories(out);
  const std::string stem = (out / (name + "." + backend)).string();
  scene::write_png(stem + ".actual.png", actual);
  if (v.diff.same_size) scene::write_png(stem + ".diff.png", v.diff.picture);
  ADD_FAILURE() << name << " on " << backend << " differs from " << golden << ": " << v.why << "; see "
                << stem << ".actual.png and .diff.png";
}

TEST_P(GoldenTest, MatchesItsScene) {
  const GoldenCase& c = cases()[std::get<1>(GetParam())];
  std::optional<Scene> s = c.make();
  if (::testing::Test::HasFailure() || !s) return;  // the scene is wrong: no pixel is worth comparing
  const scene::Camera camera = scene::fit_scene(*s, kWidth, kHeight);
  expect_golden(draw(*s, camera), c.name, render::name(std::get<0>(GetParam())));
}

// The comparison fails when a colour, a layer or the camera changes: what the goldens are
// there to catch.
TEST_P(GoldenTest, FailsWhenAColourALayerOrTheCameraChanges) {
  if (std::get<1>(GetParam()) != 0 || updating()) GTEST_SKIP() << "checked once per backend";
  std::optional<Scene> base = offcenter_case();
  ASSERT_TRUE(base);
  const scene::Camera camera = scene::fit_scene(*base, kWidth, kHeight);
  const scene::Image reference = draw(*base, camera);
  ASSERT_TRUE(compare_with(reference, draw(*base, camera)).same) << "the same scene drawn twice differs";

  Scene recoloured = *base;
  for (scene::Shape& shape : recoloured.shapes)
    if (shape.role == "circumcircle") shape.color.g = static_cast<std::uint8_t>(shape.color.g ^ 0x40);
  EXPECT_FALSE(compare_with(reference, draw(recoloured, camera)).same) << "a changed circle colour went unseen";

  Scene fewer_layers = *base;
  fewer_layers.visible.set(scene::Layer::vertices, false);
  EXPECT_FALSE(compare_with(reference, draw(fewer_layers, camera)).same) << "a missing layer went unseen";

  scene::Camera moved = camera;
  moved.pan(2.0, 0.0);
  EXPECT_FALSE(compare_with(reference, draw(*base, moved)).same) << "a camera moved by 2 pixels went unseen";
}

std::string case_name(const ::testing::TestParamInfo<GoldenTest::ParamType>& info) {
  return std::string(render::name(std::get<0>(info.param))) + "_" + cases()[std::get<1>(info.param)].name;
}

INSTANTIATE_TEST_SUITE_P(Golden, GoldenTest,
                         ::testing::Combine(::testing::Values(render::Backend::egl, render::Backend::osmesa),
                                            ::testing::Range<std::size_t>(0, cases().size())),
                         case_name);

}  // namespace
}  // namespace meshstep::golden
