// Scenes of a mesh alone and of an input alone: every fill value recomputed from the
// triangle, every colour from the map, the legends readable, the input's parts where the
// input has them, and a million triangles built quickly.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "meshstep/check/quality.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/colormap.hpp"

namespace meshstep::scene {
namespace {

std::string plate() { return std::string(MESHSTEP_ASSETS) + "/examples/plate.poly"; }

TriMesh refined_plate() {
  RefineOptions o;
  o.criteria.min_angle_deg = 30.0;
  return refine(io::read_poly(plate()), o);
}

SceneOptions fill_by(ColorBy by, double bound = 0.0) {
  SceneOptions o;
  o.color_by = by;
  o.min_angle_bound = bound;
  return o;
}

int channel_gap(Rgba a, Rgba b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
}

double area_of(const TriMesh& m, std::size_t t) {
  const Point &a = m.points[m.triangles[t][0]], &b = m.points[m.triangles[t][1]], &c = m.points[m.triangles[t][2]];
  return 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// Ticks inside the bar, in order, each label a number rounded as people write it.
void expect_readable_ticks(const Legend& legend) {
  ASSERT_FALSE(legend.ticks.empty()) << legend.title;
  for (std::size_t i = 0; i < legend.ticks.size(); ++i) {
    const Legend::Tick& t = legend.ticks[i];
    EXPECT_GE(t.at, 0.0) << legend.title;
    EXPECT_LE(t.at, 1.0) << legend.title;
    if (i) {
      EXPECT_GT(t.at, legend.ticks[i - 1].at) << legend.title << ": tick " << i;
    }
    if (legend.categorical) continue;
    char* end = nullptr;
    const double v = std::strtod(t.text.c_str(), &end);
    EXPECT_NE(end, t.text.c_str()) << "'" << t.text << "' does not start with a number";
    // At most three significant digits: "0.05", "40", "1e-05", not "0.0499999".
    char shortest[32];
    std::snprintf(shortest, sizeof shortest, "%.3g", v);
    EXPECT_EQ(std::strtod(shortest, nullptr), v) << "'" << t.text << "' is not rounded";
  }
}

TEST(SceneOfMesh, AngleValuesAndColoursAreEachTrianglesSmallestAngle) {
  const TriMesh m = refined_plate();
  const Scene s = build_scene(m, fill_by(ColorBy::angle));
  ASSERT_EQ(s.mesh.triangles, m.triangles);
  ASSERT_EQ(s.mesh.points, m.points);
  ASSERT_EQ(s.mesh.values.size(), m.triangles.size());
  ASSERT_EQ(s.mesh.fill.size(), m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& v = m.triangles[t];
    const double angle = triangle_min_angle_deg(m.points[v[0]], m.points[v[1]], m.points[v[2]]);
    EXPECT_NEAR(s.mesh.values[t], angle, 1e-9) << "triangle " << t;
    EXPECT_LE(channel_gap(s.mesh.fill[t], viridis()(angle / 60.0)), 1) << "triangle " << t;
  }
  ASSERT_TRUE(s.legend.has_value());
  EXPECT_EQ(s.legend->title, "smallest angle (°)");
  expect_readable_ticks(*s.legend);
  EXPECT_EQ(s.legend->ticks.front().text, "0");
  EXPECT_EQ(s.legend->ticks.back().text, "60");
}

// Bad triangles stand out: every triangle under the bound is on the orange side, every
// other on the blue side, and the legend marks the bound in the middle.
TEST(SceneOfMesh, QualitySplitsAtTheBound) {
  const TriMesh m = triangulate(io::read_poly(plate()));  // unrefined: many bad triangles
  const double bound = 25.0;
  const Scene s = build_scene(m, fill_by(ColorBy::quality, bound));
  std::size_t below = 0, above = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Rgba c = s.mesh.fill[t];
    if (s.mesh.values[t] < bound) {
      ++below;
      EXPECT_GT(int(c.r), int(c.b)) << "a " << s.mesh.values[t] << " degree triangle is not orange";
    } else {
      ++above;
      EXPECT_GT(int(c.b), int(c.r)) << "a " << s.mesh.values[t] << " degree triangle is not blue";
    }
  }
  EXPECT_GT(below, 0u);
  EXPECT_GT(above, 0u);
  ASSERT_TRUE(s.legend.has_value());
  expect_readable_ticks(*s.legend);
  const auto marked =
      std::find_if(s.legend->ticks.begin(), s.legend->ticks.end(), [](const Legend::Tick& t) { return t.emphasized; });
  ASSERT_NE(marked, s.legend->ticks.end());
  EXPECT_DOUBLE_EQ(marked->at, 0.5);
  EXPECT_NE(marked->text.find("25"), std::string::npos) << marked->text;
  EXPECT_EQ(
      std::count_if(s.legend->ticks.begin(), s.legend->ticks.end(), [](const Legend::Tick& t) { return t.emphasized; }),
      1);
}

TEST(SceneOfMesh, QualityBoundDefaultsTo30) {
  const Scene s = build_scene(refined_plate(), fill_by(ColorBy::quality));
  const auto marked =
      std::find_if(s.legend->ticks.begin(), s.legend->ticks.end(), [](const Legend::Tick& t) { return t.emphasized; });
  ASSERT_NE(marked, s.legend->ticks.end());
  EXPECT_EQ(marked->text.rfind("30", 0), 0u) << marked->text;
}

TEST(SceneOfMesh, AreaOnALogScale) {
  const TriMesh m = refined_plate();
  const Scene s = build_scene(m, fill_by(ColorBy::area));
  double lo = INFINITY, hi = 0.0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    EXPECT_NEAR(s.mesh.values[t], area_of(m, t), 1e-12 * area_of(m, t));
    lo = std::min(lo, area_of(m, t));
    hi = std::max(hi, area_of(m, t));
  }
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const double at = std::log(area_of(m, t) / lo) / std::log(hi / lo);
    EXPECT_LE(channel_gap(s.mesh.fill[t], cividis()(at)), 1);
  }
  ASSERT_TRUE(s.legend.has_value());
  EXPECT_NE(s.legend->title.find("log"), std::string::npos);
  expect_readable_ticks(*s.legend);
  // The tick labelled v sits where v would be on the scale.
  for (const Legend::Tick& t : s.legend->ticks) {
    const double v = std::strtod(t.text.c_str(), nullptr);
    EXPECT_NEAR(t.at, std::log(v / lo) / std::log(hi / lo), 1e-9) << t.text;
  }
}

// Three regions (attributes 7, -1.5 and 3) side by side: one colour per attribute, all
// different, and a swatch each in the legend, in order.
TEST(SceneOfMesh, RegionsAreDistinctCategories) {
  Pslg in;
  in.points = {{0, 0}, {1, 0}, {3, 0}, {4, 0}, {4, 2}, {3, 2}, {1, 2}, {0, 2}};
  for (std::uint32_t i = 0; i < 8; ++i) in.segments.push_back({i, (i + 1) % 8, 1});
  in.segments.push_back({1, 6, 2});
  in.segments.push_back({2, 5, 2});
  in.regions = {{{0.5, 1.0}, 7.0, -1.0}, {{2.0, 1.0}, -1.5, -1.0}, {{3.5, 1.0}, 3.0, -1.0}};
  RefineOptions o;
  o.criteria.min_angle_deg = 25.0;
  const TriMesh m = refine(in, o);
  ASSERT_EQ(m.attributes_per_triangle, 1u);
  const Scene s = build_scene(m, fill_by(ColorBy::region));
  std::map<double, Rgba> colour_of;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    EXPECT_EQ(s.mesh.values[t], m.triangle_attributes[t]);
    const auto [it, fresh] = colour_of.emplace(m.triangle_attributes[t], s.mesh.fill[t]);
    EXPECT_EQ(it->second, s.mesh.fill[t]) << "attribute " << m.triangle_attributes[t] << " has two colours";
  }
  ASSERT_EQ(colour_of.size(), 3u);
  std::set<std::tuple<int, int, int>> distinct;
  for (const auto& [a, c] : colour_of) distinct.insert({c.r, c.g, c.b});
  EXPECT_EQ(distinct.size(), 3u);
  ASSERT_TRUE(s.legend.has_value());
  EXPECT_TRUE(s.legend->categorical);
  ASSERT_EQ(s.legend->colors.size(), 3u);
  ASSERT_EQ(s.legend->ticks.size(), 3u);
  EXPECT_EQ(s.legend->ticks[0].text, "-1.5");
  EXPECT_EQ(s.legend->ticks[1].text, "3");
  EXPECT_EQ(s.legend->ticks[2].text, "7");
  EXPECT_EQ(s.legend->colors[0], colour_of[-1.5]);
  EXPECT_EQ(s.legend->colors[2], colour_of[7.0]);
  expect_readable_ticks(*s.legend);
}

TEST(SceneOfMesh, NoneAndAgeAreNeutralForAMeshAlone) {
  const TriMesh m = refined_plate();
  for (const Theme theme : {Theme::light, Theme::dark}) {
    SceneOptions o;
    o.theme = theme;
    const Scene plain = build_scene(m, o);
    EXPECT_FALSE(plain.legend.has_value());
    EXPECT_TRUE(plain.mesh.values.empty());
    ASSERT_EQ(plain.mesh.fill.size(), m.triangles.size());
    for (const Rgba c : plain.mesh.fill) EXPECT_EQ(c, plain.mesh.fill.front());
    // Light fill on a light background, dark on dark.
    const Rgba f = plain.mesh.fill.front();
    EXPECT_EQ(f.r + f.g + f.b > 3 * 128, theme == Theme::light);
    EXPECT_EQ(plain.background.r > 128, theme == Theme::light);
    o.color_by = ColorBy::age;
    const Scene aged = build_scene(m, o);
    for (const Rgba c : aged.mesh.fill) EXPECT_EQ(c, aged.mesh.fill.front()) << "a mesh file has no history";
  }
}

TEST(SceneOfMesh, SegmentsVerticesAndCaption) {
  TriMesh m = refined_plate();
  m.input_vertex_count = 45;  // as the plate's input had
  m.holes = {{2.5, 3.0}, {7.5, 3.0}};
  const Scene s = build_scene(m, {});
  const Shape* seg = s.find("segments");
  ASSERT_NE(seg, nullptr);
  EXPECT_EQ(seg->layer, Layer::segments);
  EXPECT_EQ(seg->kind, ShapeKind::lines);
  ASSERT_EQ(seg->points.size(), 2 * m.segments.size());
  for (std::size_t i = 0; i < m.segments.size(); ++i) {
    EXPECT_EQ(seg->points[2 * i], m.points[m.segments[i].a]);
    EXPECT_EQ(seg->points[2 * i + 1], m.points[m.segments[i].b]);
  }
  EXPECT_GT(seg->width_px, s.mesh.edge_width_px) << "segments are thicker than edges";
  EXPECT_NE(seg->color, s.mesh.edge_color);
  const Shape *input = s.find("input_vertices"), *steiner = s.find("steiner_vertices");
  ASSERT_NE(input, nullptr);
  ASSERT_NE(steiner, nullptr);
  EXPECT_EQ(input->points, std::vector<Point>(m.points.begin(), m.points.begin() + 45));
  EXPECT_EQ(steiner->points, std::vector<Point>(m.points.begin() + 45, m.points.end()));
  EXPECT_NE(input->marker, steiner->marker);
  EXPECT_NE(input->fill, steiner->fill);
  const Shape* holes = s.find("holes");
  ASSERT_NE(holes, nullptr);
  EXPECT_EQ(holes->marker, Marker::cross);
  EXPECT_EQ(holes->points, m.holes);
  EXPECT_EQ(s.caption,
            std::to_string(m.triangles.size()) + " triangles, " + std::to_string(m.points.size()) + " vertices");

  SceneOptions few;
  few.max_vertex_markers = m.points.size() - 1;
  const Scene crowded = build_scene(m, few);
  EXPECT_EQ(crowded.find("input_vertices"), nullptr);
  EXPECT_EQ(crowded.find("steiner_vertices"), nullptr);
  // The mesh's box: the plate is 10 x 6.
  EXPECT_EQ(s.bounds.lo, (Point{0, 0}));
  EXPECT_EQ(s.bounds.hi, (Point{10, 6}));
}

TEST(SceneOfInput, HasTheInputsPointsSegmentsAndHoles) {
  const Pslg in = io::read_poly(plate());
  const Scene s = build_scene(in, {});
  EXPECT_TRUE(s.mesh.triangles.empty());
  const Shape* points = s.find("input_vertices");
  ASSERT_NE(points, nullptr);
  EXPECT_EQ(points->points, in.points);
  EXPECT_EQ(s.find("steiner_vertices"), nullptr);
  const Shape* seg = s.find("segments");
  ASSERT_NE(seg, nullptr);
  ASSERT_EQ(seg->points.size(), 2 * in.segments.size());
  for (std::size_t i = 0; i < in.segments.size(); ++i) {
    EXPECT_EQ(seg->points[2 * i], in.points[in.segments[i].a]);
    EXPECT_EQ(seg->points[2 * i + 1], in.points[in.segments[i].b]);
  }
  const Shape* holes = s.find("holes");
  ASSERT_NE(holes, nullptr);
  EXPECT_EQ(holes->points, in.holes);
  EXPECT_EQ(holes->layer, Layer::holes);
  EXPECT_EQ(s.caption, "input: 45 vertices, 41 segments, 2 holes");
  EXPECT_EQ(s.bounds.lo, (Point{0, 0}));
  EXPECT_EQ(s.bounds.hi, (Point{10, 6}));
}

// A grid of a million triangles, filled by each quantity: the time is printed (the goal is
// well under 100 ms in a release build); the bound asserted only catches a blow-up.
TEST(SceneOfMesh, AMillionTrianglesBuildQuickly) {
  constexpr std::uint32_t n = 708;  // (n - 1)^2 squares, two triangles each: 999,698
  TriMesh m;
  m.points.reserve(n * n);
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i)
      m.points.push_back({i + 0.1 * std::sin(j * 1.3), j + 0.1 * std::cos(i * 0.7)});
  for (std::uint32_t j = 0; j + 1 < n; ++j)
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
      const std::uint32_t a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  m.attributes_per_triangle = 1;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) m.triangle_attributes.push_back(double(t / 100000));
  m.input_vertex_count = m.points.size();
  for (const ColorBy by : {ColorBy::none, ColorBy::angle, ColorBy::quality, ColorBy::area, ColorBy::region}) {
    const auto start = std::chrono::steady_clock::now();
    const Scene s = build_scene(m, fill_by(by));
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ scene    ] %zu triangles, fill by %s: %.1f ms\n", m.triangles.size(), name(by), ms);
    EXPECT_EQ(s.mesh.fill.size(), m.triangles.size());
    EXPECT_LT(ms, 5000.0);
    EXPECT_EQ(s.find("input_vertices"), nullptr) << "too many vertices for markers";
  }
}

}  // namespace
}  // namespace meshstep::scene
