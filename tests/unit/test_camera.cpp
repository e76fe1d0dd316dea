// The camera: fitting keeps the aspect ratio and the margins, a world window is shown
// whole, zoom keeps the point under the pointer, pan moves the world with the pointer.
#include <gtest/gtest.h>

#include "meshstep/scene/camera.hpp"

namespace {

using meshstep::BBox;
using meshstep::Point;
using meshstep::scene::Camera;
using meshstep::scene::Margins;

BBox box(double x0, double y0, double x1, double y1) {
  BBox b;
  b.add({x0, y0});
  b.add({x1, y1});
  return b;
}

TEST(Camera, FitCentresTheBoxAndKeepsTheMarginOnTheTightSide) {
  // A 2:1 box in a 1000x400 picture with a 20 px margin: the height is the tight side.
  const Camera c = Camera::fit(box(0, 0, 20, 10), 1000, 400, 20.0);
  EXPECT_DOUBLE_EQ(c.pixels_per_unit(), 36.0);  // (400 - 40) / 10
  const Point lo = c.to_screen({0, 0}), hi = c.to_screen({20, 10});
  EXPECT_DOUBLE_EQ(lo.y, 380.0);  // world y up, screen y down
  EXPECT_DOUBLE_EQ(hi.y, 20.0);
  EXPECT_DOUBLE_EQ(lo.x + hi.x, 1000.0);  // centred horizontally
}

TEST(Camera, FitLeavesUnevenMarginsFree) {
  const Margins m{10.0, 50.0, 150.0, 10.0};
  const Camera c = Camera::fit(box(-1, -1, 1, 1), 800, 600, m);
  const Point lo = c.to_screen({-1, -1}), hi = c.to_screen({1, 1});
  // The free area is x in [10, 650], y in [50, 590]: 640 x 540, so the square is 540 px.
  EXPECT_NEAR(hi.x - lo.x, 540.0, 1e-9);
  EXPECT_NEAR(hi.y, 50.0, 1e-9);
  EXPECT_NEAR(lo.y, 590.0, 1e-9);
  EXPECT_NEAR(0.5 * (lo.x + hi.x), 330.0, 1e-9);  // centre of [10, 650]
}

TEST(Camera, WindowShowsTheWholeWindowAndWidensTheLooseDirection) {
  const Camera c = Camera::window(box(2, 3, 4, 4), 400, 400);
  const BBox v = c.visible();
  EXPECT_DOUBLE_EQ(v.lo.x, 2.0);
  EXPECT_DOUBLE_EQ(v.hi.x, 4.0);
  EXPECT_DOUBLE_EQ(v.lo.y, 2.5);  // 1 unit high window shown 2 units high, centred
  EXPECT_DOUBLE_EQ(v.hi.y, 4.5);
}

TEST(Camera, ScreenAndWorldAreInverse) {
  const Camera c = Camera::fit(box(1e6, -3e6, 1.5e6, -2e6), 1280, 720);
  for (const Point p : {Point{1.2e6, -2.5e6}, Point{1e6, -3e6}}) {
    const Point back = c.to_world(c.to_screen(p));
    EXPECT_NEAR(back.x, p.x, 1e-6);
    EXPECT_NEAR(back.y, p.y, 1e-6);
  }
}

TEST(Camera, ZoomKeepsThePointUnderThePointer) {
  Camera c = Camera::fit(box(0, 0, 10, 10), 500, 500);
  const double scale = c.pixels_per_unit();
  const Point pointer{123.0, 321.0};
  const Point before = c.to_world(pointer);
  c.zoom_at(pointer, 3.0);
  const Point after = c.to_world(pointer);
  EXPECT_NEAR(after.x, before.x, 1e-12);
  EXPECT_NEAR(after.y, before.y, 1e-12);
  EXPECT_DOUBLE_EQ(c.pixels_per_unit(), 3.0 * scale);
}

TEST(Camera, PanMovesTheWorldWithThePointer) {
  Camera c = Camera::fit(box(0, 0, 10, 10), 500, 500);
  const Point p{3.0, 4.0};
  const Point s = c.to_screen(p);
  c.pan(15.0, -7.0);
  const Point moved = c.to_screen(p);
  EXPECT_NEAR(moved.x, s.x + 15.0, 1e-9);
  EXPECT_NEAR(moved.y, s.y - 7.0, 1e-9);
}

TEST(Camera, DegenerateBoxesGetAUsableWindow) {
  BBox empty;
  EXPECT_GT(Camera::fit(empty, 100, 100).pixels_per_unit(), 0.0);
  const Camera point = Camera::fit(box(5, 5, 5, 5), 100, 100);
  EXPECT_GT(point.pixels_per_unit(), 0.0);
  EXPECT_NEAR(point.to_screen({5, 5}).x, 50.0, 1e-9);
  const Camera line = Camera::fit(box(0, 1, 10, 1), 100, 100, 0.0);
  EXPECT_DOUBLE_EQ(line.pixels_per_unit(), 10.0);
}

}  // namespace
