// The workbench's edit model (pslg/pslg_editor.hpp) and its .poly writer (io: write_pslg).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/io/write_pslg.hpp"
#include "meshstep/pslg/pslg_editor.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Two inputs equal bit for bit: every coordinate, index, marker, attribute and area.
void expect_identical(const Pslg& a, const Pslg& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_TRUE(same_bits(a.points[i].x, b.points[i].x)) << "vertex " << i << " x " << a.points[i].x << " vs " << b.points[i].x;
    EXPECT_TRUE(same_bits(a.points[i].y, b.points[i].y)) << "vertex " << i << " y " << a.points[i].y << " vs " << b.points[i].y;
  }
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t s = 0; s < a.segments.size(); ++s) {
    EXPECT_EQ(a.segments[s].a, b.segments[s].a) << "segment " << s;
    EXPECT_EQ(a.segments[s].b, b.segments[s].b) << "segment " << s;
    EXPECT_EQ(a.segments[s].marker, b.segments[s].marker) << "segment " << s;
  }
  EXPECT_EQ(a.has_segment_markers, b.has_segment_markers);
  EXPECT_EQ(a.has_vertex_markers, b.has_vertex_markers);
  EXPECT_EQ(a.vertex_markers, b.vertex_markers);
  EXPECT_EQ(a.attributes_per_vertex, b.attributes_per_vertex);
  ASSERT_EQ(a.vertex_attributes.size(), b.vertex_attributes.size());
  for (std::size_t i = 0; i < a.vertex_attributes.size(); ++i)
    EXPECT_TRUE(same_bits(a.vertex_attributes[i], b.vertex_attributes[i]));
  ASSERT_EQ(a.holes.size(), b.holes.size());
  for (std::size_t h = 0; h < a.holes.size(); ++h) {
    EXPECT_TRUE(same_bits(a.holes[h].x, b.holes[h].x));
    EXPECT_TRUE(same_bits(a.holes[h].y, b.holes[h].y));
  }
  ASSERT_EQ(a.regions.size(), b.regions.size());
  for (std::size_t r = 0; r < a.regions.size(); ++r) {
    EXPECT_TRUE(same_bits(a.regions[r].point.x, b.regions[r].point.x));
    EXPECT_TRUE(same_bits(a.regions[r].point.y, b.regions[r].point.y));
    EXPECT_TRUE(same_bits(a.regions[r].attribute, b.regions[r].attribute));
    EXPECT_TRUE(same_bits(a.regions[r].max_area, b.regions[r].max_area));
  }
  EXPECT_EQ(a.first_index, b.first_index);
}

// A 4x3 rectangle with a 1x1 square hole, drawn as a person would: segments by their ends.
void draw_rectangle_with_hole(PslgEditor& e) {
  const double tol = 1e-9;
  e.add_segment({0, 0}, {4, 0}, tol);
  e.add_segment({4, 0}, {4, 3}, tol);
  e.add_segment({4, 3}, {0, 3}, tol);
  e.add_segment({0, 3}, {0, 0}, tol);
  e.add_segment({1.5, 1}, {2.5, 1}, tol);
  e.add_segment({2.5, 1}, {2.5, 2}, tol);
  e.add_segment({2.5, 2}, {1.5, 2}, tol);
  e.add_segment({1.5, 2}, {1.5, 1}, tol);
  e.add_hole({2, 1.5});
}

double area(const TriMesh& m) {
  double total = 0;
  for (const auto& t : m.triangles) {
    const Point a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
    total += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return total;
}

TEST(PslgEditor, SegmentsSnapToVerticesSoAClosedRectangleHasFourVertices) {
  PslgEditor e;
  draw_rectangle_with_hole(e);
  EXPECT_EQ(e.input().points.size(), 8u);
  EXPECT_EQ(e.input().segments.size(), 8u);
  EXPECT_EQ(e.input().holes.size(), 1u);
  // The drawn input triangulates to the rectangle minus the hole.
  const TriMesh m = triangulate(e.input());
  EXPECT_DOUBLE_EQ(area(m), 12.0 - 1.0);
}

TEST(PslgEditor, UndoAndRedoRestoreEveryStateExactly) {
  PslgEditor e;
  std::vector<Pslg> states{e.input()};
  e.add_vertex({0.1, 0.2});
  states.push_back(e.input());
  e.add_vertex({1.0 / 3.0, 1e-300});
  states.push_back(e.input());
  e.add_segment(0u, 1u);
  states.push_back(e.input());
  e.move_vertex(0, {std::nextafter(0.1, 1.0), -0.0});
  states.push_back(e.input());
  e.add_region({{0.3, 0.1}, 7.0, 0.25});
  states.push_back(e.input());
  e.set_region(0, {{0.3, 0.1}, 8.0, -1.0});
  states.push_back(e.input());
  e.delete_vertex(0);  // and segment 0 with it
  states.push_back(e.input());
  EXPECT_EQ(e.input().segments.size(), 0u);
  EXPECT_EQ(e.undo_depth(), states.size() - 1);
  for (std::size_t i = states.size() - 1; i-- > 0;) {
    ASSERT_TRUE(e.undo());
    expect_identical(e.input(), states[i]);
  }
  EXPECT_FALSE(e.undo());
  for (std::size_t i = 1; i < states.size(); ++i) {
    ASSERT_TRUE(e.redo());
    expect_identical(e.input(), states[i]);
  }
  EXPECT_FALSE(e.redo());
}

TEST(PslgEditor, UndoingAMoveRestoresTheExactBits) {
  PslgEditor e;
  const Point start{0.1 + 0.2, -1e-310};  // 0.30000000000000004 and a subnormal
  e.add_vertex(start);
  for (int i = 0; i < 100; ++i) e.move_vertex(0, {e.input().points[0].x * 1.1, e.input().points[0].y + 0.1});
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(e.undo());
  EXPECT_TRUE(same_bits(e.input().points[0].x, start.x));
  EXPECT_TRUE(same_bits(e.input().points[0].y, start.y));
}

TEST(PslgEditor, DeletingAVertexRenumbersTheSegmentsAndUndoPutsThemBack) {
  PslgEditor e;
  draw_rectangle_with_hole(e);
  const Pslg before = e.input();
  e.delete_vertex(1);  // the rectangle's (4, 0): two segments go with it
  EXPECT_EQ(e.input().points.size(), 7u);
  EXPECT_EQ(e.input().segments.size(), 6u);
  for (const Segment& s : e.input().segments) {
    EXPECT_LT(s.a, 7u);
    EXPECT_LT(s.b, 7u);
  }
  // The hole's square is intact, renumbered: its segments still join the same points.
  for (std::size_t s = 2; s < 6; ++s) {
    const Segment& now = e.input().segments[s];
    const Segment& was = before.segments[s + 2];
    EXPECT_EQ(e.input().points[now.a].x, before.points[was.a].x);
    EXPECT_EQ(e.input().points[now.b].y, before.points[was.b].y);
  }
  e.undo();
  expect_identical(e.input(), before);
}

TEST(PslgEditor, NewEmptiesTheInputAndIsUndoneLikeAnyEdit) {
  PslgEditor e;
  draw_rectangle_with_hole(e);
  const Pslg before = e.input();
  e.clear();
  EXPECT_TRUE(e.input().points.empty());
  EXPECT_TRUE(e.input().segments.empty());
  EXPECT_TRUE(e.input().holes.empty());
  e.undo();
  expect_identical(e.input(), before);
}

TEST(PslgEditor, AnEditAfterUndoDropsTheRedo) {
  PslgEditor e;
  e.add_vertex({0, 0});
  e.add_vertex({1, 0});
  e.undo();
  EXPECT_TRUE(e.can_redo());
  e.add_vertex({2, 0});
  EXPECT_FALSE(e.can_redo());
  EXPECT_EQ(e.input().points.back().x, 2.0);
}

TEST(PslgEditor, RefusesWhatMakesNoSenseAndChangesNothing) {
  PslgEditor e;
  e.add_vertex({0, 0});
  e.add_vertex({1, 0});
  e.add_segment(0u, 1u);
  const std::uint64_t revision = e.revision();
  EXPECT_THROW(e.add_segment(0u, 0u), EditRefused);
  EXPECT_THROW(e.add_segment(1u, 0u), EditRefused);  // joined already
  EXPECT_THROW(e.add_segment(0u, 9u), EditRefused);
  EXPECT_THROW(e.add_vertex({std::nan(""), 0}), EditRefused);
  EXPECT_THROW(e.add_hole({0, std::numeric_limits<double>::infinity()}), EditRefused);
  EXPECT_THROW(e.move_vertex(5, {0, 0}), EditRefused);
  EXPECT_THROW(e.delete_hole(0), EditRefused);
  EXPECT_THROW(e.add_segment(Point{0, 0}, Point{1e-12, 0}, 1e-9), EditRefused);  // both ends snap to vertex 0
  EXPECT_THROW(e.add_segment(Point{5, 5}, Point{5, 5}, 1e-9), EditRefused);      // a point, not a segment
  EXPECT_EQ(e.input().points.size(), 2u);  // the refused segment's first end was not kept
  EXPECT_EQ(e.revision(), revision);
  try {
    e.add_segment(1u, 0u);
  } catch (const EditRefused& x) {
    EXPECT_STREQ(x.what(), "add segment: vertices 1 and 0 are joined already (segment 0)");
  }
}

TEST(PslgEditor, ElementNearPicksPointsBeforeSegments) {
  PslgEditor e;
  draw_rectangle_with_hole(e);
  e.add_region({{0.5, 0.5}, 2.0, 0.1});
  EXPECT_EQ(e.element_near({0.001, 0}, 0.01), (ElementRef{InputElement::vertex, 0}));
  EXPECT_EQ(e.element_near({2, 0.001}, 0.01), (ElementRef{InputElement::segment, 0}));
  EXPECT_EQ(e.element_near({2, 1.5}, 0.01), (ElementRef{InputElement::hole, 0}));
  EXPECT_EQ(e.element_near({0.5, 0.5}, 0.01), (ElementRef{InputElement::region, 0}));
  EXPECT_EQ(e.element_near({3, 2.5}, 0.01).kind, InputElement::none);
  e.erase(e.element_near({2, 0.001}, 0.01));
  EXPECT_EQ(e.input().segments.size(), 7u);
  e.move(e.element_near({2, 1.5}, 0.01), {2, 1.25});
  EXPECT_EQ(e.input().holes[0].y, 1.25);
}

TEST(PslgEditor, SavedPolyReadsBackBitForBit) {
  testing::TempDir dir;
  PslgEditor e;
  draw_rectangle_with_hole(e);
  // Awkward coordinates: no short decimal (0.1, 1/3), a subnormal, the largest double,
  // negative zero (kept: it is written "-0"), and a region without an area bound (-1).
  e.add_vertex({0.1, 1.0 / 3.0});
  e.add_vertex({1e-300, -0.0});
  e.add_vertex({4.9e-324, std::numeric_limits<double>::max()});
  e.add_region({{0.5, 0.5}, 0.1, -1.0});
  e.add_region({{3.5, 2.5}, -2.0, 1e-5});
  const std::string path = dir.file("drawn.poly");
  io::write_pslg(path, e.input());
  expect_identical(io::read_poly(path), e.input());
}

TEST(PslgEditor, SavedPolyKeepsMarkersAttributesAndOneBasedNumbering) {
  testing::TempDir dir;
  const std::string original = dir.write("marked.poly",
                                         "3 2 1 1\n1 0 0 0.5 7\n2 1 0 1.5 8\n3 0 1 2.5 9\n"
                                         "2 1\n1 1 2 4\n2 2 3 5\n0\n0\n");
  PslgEditor e(io::read_poly(original));
  e.add_vertex({0.25, 0.25});  // marker 0, attribute 0
  e.add_segment(2u, 3u);
  const std::string path = dir.file("saved.poly");
  io::write_pslg(path, e.input());
  const Pslg back = io::read_poly(path);
  expect_identical(back, e.input());
  EXPECT_EQ(back.first_index, 1);
  EXPECT_EQ(back.vertex_markers, (std::vector<int>{7, 8, 9, 0}));
  EXPECT_EQ(back.vertex_attributes, (std::vector<double>{0.5, 1.5, 2.5, 0.0}));
}

TEST(PslgEditor, WritingRefusesANonFiniteNumberAndLeavesTheFileAsItWas) {
  testing::TempDir dir;
  const std::string path = dir.write("keep.poly", "unchanged");
  Pslg bad;
  bad.points = {{0, 0}, {1, std::numeric_limits<double>::infinity()}};
  EXPECT_THROW(io::write_pslg(path, bad), InputError);
  std::ifstream in(path);
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "unchanged");
}

}  // namespace
}  // namespace meshstep
