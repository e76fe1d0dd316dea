// Labels avoid each other and the vertices (issue 29, item 3; scene/label_placement.hpp):
// where labels asked for places that overlap, the placed boxes are disjoint, none covers a
// vertex marker, the step's words keep the place they asked for, and the result is the same
// every time. Then every moment of a recorded refinement of lesson.poly at 1280x720.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/label_placement.hpp"
#include "meshstep/scene/layout.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep::scene {
namespace {

struct Box {
  double x0, y0, x1, y1;
};
bool overlap(const Box& a, const Box& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }
Box box_of(const PlacedLabel& p) { return {p.x0, p.y0, p.x1, p.y1}; }

// The box a label would cover where it asks to be (as the renderers drew every label before).
Box asked_box(const Scene& s, const Camera& camera, const Label& l) {
  const Point at = camera.to_screen(l.at);
  const double x = std::round(at.x + l.dx_px * s.text_scale), base = std::round(at.y + l.dy_px * s.text_scale);
  const TextExtent e = estimated_text_extent(l.text, l.size_px * s.text_scale);
  return {x - 2.0, base - e.ascent, x + e.width + 2.0, base + e.descent};
}

void expect_disjoint_and_clear_of_vertices(const Scene& s, const Camera& camera, const std::vector<PlacedLabel>& placed,
                                           const std::string& where) {
  for (std::size_t i = 0; i < placed.size(); ++i)
    for (std::size_t j = i + 1; j < placed.size(); ++j)
      EXPECT_FALSE(overlap(box_of(placed[i]), box_of(placed[j])))
          << where << ": '" << s.labels[placed[i].label].text << "' and '" << s.labels[placed[j].label].text << "' overlap";
  for (const Shape& shape : s.shapes) {
    if (shape.kind != ShapeKind::markers || (shape.layer != Layer::vertices && shape.layer != Layer::overlay)) continue;
    for (const Point& p : shape.points) {
      const Point at = camera.to_screen(p);
      const double r = 0.5 * shape.marker_px;
      for (const PlacedLabel& l : placed)
        EXPECT_FALSE(overlap(box_of(l), {at.x - r, at.y - r, at.x + r, at.y + r}))
            << where << ": '" << s.labels[l.label].text << "' covers a " << shape.role << " marker";
    }
  }
}

// Three labels at one point asking for one place, and vertex markers round it: what a
// split on a concentric shell showed ("midpoint" over "rejected: encroaches").
Scene crowded_scene() {
  Scene s;
  s.visible.set(Layer::caption, false);
  Shape vertices;
  vertices.layer = Layer::vertices;
  vertices.kind = ShapeKind::markers;
  vertices.role = "input_vertices";
  vertices.marker_px = 7.0f;
  vertices.points = {{10.0, 10.0}, {10.3, 9.9}, {9.8, 10.25}, {11.0, 10.0}};
  s.shapes.push_back(vertices);
  s.labels.push_back({{10.0, 10.0}, "7", {}, 13.0f, 7.0f, -7.0f, 0});
  s.labels.push_back({{10.0, 10.0}, "midpoint", {}, 13.0f, 10.0f, -10.0f});
  s.labels.push_back({{10.05, 10.0}, "rejected: encroaches", {}, 13.0f, 10.0f, -10.0f});
  s.labels.push_back({{10.3, 9.9}, "12", {}, 13.0f, 7.0f, -7.0f, 0});
  return s;
}

TEST(LabelPlacement, LabelsThatAskedForOnePlaceGetDisjointOnes) {
  const Scene s = crowded_scene();
  const Camera camera({10.0, 10.0}, 100.0, 1280, 720);
  // They did overlap where they asked to be.
  EXPECT_TRUE(overlap(asked_box(s, camera, s.labels[1]), asked_box(s, camera, s.labels[2])));
  const std::vector<PlacedLabel> placed = place_labels(s, camera, estimated_text_extent);
  ASSERT_EQ(placed.size(), s.labels.size()) << "room for all four round their points";
  expect_disjoint_and_clear_of_vertices(s, camera, placed, "crowded");
  // The step's first words keep their place; the vertex names moved out of their way.
  const Box midpoint = asked_box(s, camera, s.labels[1]);
  EXPECT_EQ(placed[1].x0, midpoint.x0);
  EXPECT_EQ(placed[1].y0, midpoint.y0);
  // Deterministic.
  const std::vector<PlacedLabel> again = place_labels(s, camera, estimated_text_extent);
  ASSERT_EQ(again.size(), placed.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    EXPECT_EQ(again[i].label, placed[i].label);
    EXPECT_EQ(again[i].left, placed[i].left);
    EXPECT_EQ(again[i].baseline, placed[i].baseline);
  }
}

// With no free place near its point, the least important label is left out rather than drawn
// over another.
TEST(LabelPlacement, ALabelWithNoFreePlaceIsLeftOut) {
  Scene s;
  s.visible.set(Layer::caption, false);
  for (int i = 0; i < 60; ++i) s.labels.push_back({{0.0, 0.0}, "a long label " + std::to_string(i), {}, 13.0f, 10.0f, -10.0f, 0});
  s.labels.push_back({{0.0, 0.0}, "the step's words", {}, 13.0f, 10.0f, -10.0f, 2});
  const Camera camera({0.0, 0.0}, 10.0, 640, 400);
  const std::vector<PlacedLabel> placed = place_labels(s, camera, estimated_text_extent);
  EXPECT_LT(placed.size(), s.labels.size());
  expect_disjoint_and_clear_of_vertices(s, camera, placed, "sixty at a point");
  ASSERT_FALSE(placed.empty());
  EXPECT_EQ(placed.back().label, s.labels.size() - 1) << "the most important label is placed";
}

// A recorded refinement of lesson.poly, every step at 1280x720 fitted as `render` fits it,
// at UI scales 1 and 1.5: no two labels overlap and none covers a vertex.
TEST(LabelPlacement, EveryStepOfTheLessonAt1280x720) {
  testing::TempDir dir("meshstep_labels_");
  const std::string log_path = dir.file("lesson.mslog");
  const testing::CommandResult run = testing::run_meshstep(
      "refine " + std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly --algorithm offcenter --min-angle 30 --record " +
          log_path + " -o " + dir.file("out") + " -q",
      dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  const replay::LogReader log(log_path);
  replay::Replay cursor(log);
  std::size_t labelled = 0, asked_overlaps = 0;
  for (std::uint64_t k = 0; k <= log.step_count(); ++k) {
    cursor.seek_event(replay::step_position(log, k));
    for (const float scale : {1.0f, 1.5f}) {
      SceneOptions options;
      options.text_scale = scale;
      const Scene s = build_scene(cursor, options);
      const Camera camera = fit_scene(s, 1280, 720);
      const std::vector<PlacedLabel> placed = place_labels(s, camera, estimated_text_extent);
      labelled += !placed.empty();
      for (std::size_t i = 0; i < s.labels.size(); ++i)
        for (std::size_t j = i + 1; j < s.labels.size(); ++j)
          asked_overlaps += overlap(asked_box(s, camera, s.labels[i]), asked_box(s, camera, s.labels[j]));
      expect_disjoint_and_clear_of_vertices(s, camera, placed, "step " + std::to_string(k));
    }
  }
  EXPECT_GT(labelled, 10u);
  EXPECT_GT(asked_overlaps, 0u) << "some moment had labels asking for overlapping places";
}

// Does segment p-q touch the box? An end inside, or a crossing of one of its four sides.
bool segment_meets_box(const Point& p, const Point& q, const Box& b) {
  const auto in = [&](const Point& x) { return x.x > b.x0 && x.x < b.x1 && x.y > b.y0 && x.y < b.y1; };
  if (in(p) || in(q)) return true;
  const auto orient = [](const Point& a, const Point& c, const Point& d) {
    return (c.x - a.x) * (d.y - a.y) - (c.y - a.y) * (d.x - a.x);
  };
  const auto cross = [&](const Point& a, const Point& c) {
    return orient(p, q, a) * orient(p, q, c) < 0 && orient(a, c, p) * orient(a, c, q) < 0;
  };
  const Point tl{b.x0, b.y0}, tr{b.x1, b.y0}, br{b.x1, b.y1}, bl{b.x0, b.y1};
  return cross(tl, tr) || cross(tr, br) || cross(br, bl) || cross(bl, tl);
}

// Step 0 of lesson.poly at 1280x720: the fourteen vertex names all show, and none lies on a
// segment of the outline, the hole or the crack (there is room beside every vertex).
TEST(LabelPlacement, VertexNamesAtStepZeroStayOffTheSegments) {
  testing::TempDir dir("meshstep_labels_");
  const std::string log_path = dir.file("lesson.mslog");
  const testing::CommandResult run = testing::run_meshstep(
      "refine " + std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly --min-angle 30 --record " + log_path + " -o " +
          dir.file("out") + " -q",
      dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  const replay::LogReader log(log_path);
  replay::Replay cursor(log);
  cursor.seek_event(replay::step_position(log, 0));
  const Scene s = build_scene(cursor, SceneOptions{});
  const Camera camera = fit_scene(s, 1280, 720);
  const std::vector<PlacedLabel> placed = place_labels(s, camera, estimated_text_extent);
  ASSERT_EQ(placed.size(), 14u);
  const Shape* segments = s.find("segments");
  ASSERT_NE(segments, nullptr);
  std::size_t asked_on_a_segment = 0;
  for (const PlacedLabel& l : placed) {
    const Box asked = asked_box(s, camera, s.labels[l.label]);
    for (std::size_t i = 0; i + 1 < segments->points.size(); i += 2) {
      const Point p = camera.to_screen(segments->points[i]), q = camera.to_screen(segments->points[i + 1]);
      EXPECT_FALSE(segment_meets_box(p, q, box_of(l))) << "vertex " << s.labels[l.label].text << "'s name is on a segment";
      asked_on_a_segment += segment_meets_box(p, q, asked);
    }
  }
  EXPECT_GT(asked_on_a_segment, 0u) << "where they asked to be, some names were on segments";
}

}  // namespace
}  // namespace meshstep::scene
