// Screen-space geometry for the SVG writer: what is visible, and cutting what reaches far
// off the picture down to a guard box around it.
//
// Why cut at all: zoomed in, a triangle or a circumcircle can reach millions of pixels
// off the picture. Renderers rasterise in fixed point (cairo, under rsvg and Firefox,
// wraps beyond about 8 million pixels) and the file would print huge numbers. Anything
// that stays inside the guard box (the picture grown by kGuardPx on every side) is written
// as it is; anything reaching beyond is cut to the guard box, whose sides are too far off
// the picture for the cut to show.
#pragma once

#include <vector>

#include "meshstep/geometry/point.hpp"

namespace meshstep::scene::detail {

inline constexpr double kGuardPx = 4096.0;

struct ScreenBox {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;

  ScreenBox grown(double d) const { return {x0 - d, y0 - d, x1 + d, y1 + d}; }
  bool contains(Point p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
  // Whether the box [lo, hi] overlaps this one (touching counts).
  bool overlaps(Point lo, Point hi) const { return lo.x <= x1 && hi.x >= x0 && lo.y <= y1 && hi.y >= y0; }
};

// The segment cut to the box (Liang-Barsky); false when nothing of it is inside.
bool clip_segment(Point& a, Point& b, const ScreenBox& box);

// The part of a convex or simple polygon inside the box (Sutherland-Hodgman), into `out`
// (emptied first; fewer than 3 points: nothing inside).
void clip_polygon(const std::vector<Point>& polygon, const ScreenBox& box, std::vector<Point>& out);

// A circle as points for the part of it that matters inside `box`, each chord within
// `tolerance_px` of the arc. A circle around a point of the box comes whole (`closed`);
// otherwise the arc spans the angles under which the centre sees the box, and the
// polygon arc + centre covers the disc's part inside the box.
struct CircleOutline {
  std::vector<Point> points;
  bool closed = false;
};
CircleOutline circle_outline(Point center, double radius, const ScreenBox& box, double tolerance_px);

}  // namespace meshstep::scene::detail
