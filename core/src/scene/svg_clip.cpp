#include "scene/svg_clip.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace meshstep::scene::detail {

bool clip_segment(Point& a, Point& b, const ScreenBox& box) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  double t0 = 0.0, t1 = 1.0;
  // For each side: p * t <= q keeps the point inside.
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - box.x0, box.x1 - a.x, a.y - box.y0, box.y1 - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;  // parallel to this side and outside it
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  const Point start = a;
  if (t1 < 1.0) b = {start.x + t1 * dx, start.y + t1 * dy};
  if (t0 > 0.0) a = {start.x + t0 * dx, start.y + t0 * dy};
  return true;
}

namespace {

// Keeps the part of `in` on the inner side of one box side: inside(p) says which side,
// cross(p, q) is where the edge p-q crosses it.
template <class Inside, class Cross>
void clip_side(const std::vector<Point>& in, std::vector<Point>& out, Inside inside, Cross cross) {
  out.clear();
  if (in.empty()) return;
  Point prev = in.back();
  bool prev_in = inside(prev);
  for (const Point& p : in) {
    const bool p_in = inside(p);
    if (p_in != prev_in) out.push_back(cross(prev, p));
    if (p_in) out.push_back(p);
    prev = p;
    prev_in = p_in;
  }
}

Point cross_x(Point p, Point q, double x) { return {x, p.y + (q.y - p.y) * (x - p.x) / (q.x - p.x)}; }
Point cross_y(Point p, Point q, double y) { return {p.x + (q.x - p.x) * (y - p.y) / (q.y - p.y), y}; }

}  // namespace

void clip_polygon(const std::vector<Point>& polygon, const ScreenBox& box, std::vector<Point>& out) {
  std::vector<Point> tmp;
  clip_side(polygon, out, [&](Point p) { return p.x >= box.x0; }, [&](Point p, Point q) { return cross_x(p, q, box.x0); });
  clip_side(out, tmp, [&](Point p) { return p.x <= box.x1; }, [&](Point p, Point q) { return cross_x(p, q, box.x1); });
  clip_side(tmp, out, [&](Point p) { return p.y >= box.y0; }, [&](Point p, Point q) { return cross_y(p, q, box.y0); });
  clip_side(out, tmp, [&](Point p) { return p.y <= box.y1; }, [&](Point p, Point q) { return cross_y(p, q, box.y1); });
  out.swap(tmp);
  if (out.size() < 3) out.clear();
}

CircleOutline circle_outline(Point center, double radius, const ScreenBox& box, double tolerance_px) {
  constexpr double kPi = std::numbers::pi;
  constexpr std::size_t kMaxSteps = 1 << 14;
  CircleOutline outline;
  double from = -kPi, span = 2.0 * kPi;
  outline.closed = box.contains(center);
  if (!outline.closed) {
    // The centre is outside the (convex) box, so the box fills less than half a turn as
    // seen from it: the corners' extreme angles around the direction to the box's middle.
    const double towards = std::atan2(0.5 * (box.y0 + box.y1) - center.y, 0.5 * (box.x0 + box.x1) - center.x);
    double lo = 0.0, hi = 0.0;
    for (const Point corner : {Point{box.x0, box.y0}, Point{box.x1, box.y0}, Point{box.x0, box.y1}, Point{box.x1, box.y1}}) {
      const double turn = std::remainder(std::atan2(corner.y - center.y, corner.x - center.x) - towards, 2.0 * kPi);
      lo = std::min(lo, turn);
      hi = std::max(hi, turn);
    }
    from = towards + lo;
    span = hi - lo;
  }
  // A chord of angle s is at most r (1 - cos(s / 2)) ~ r s^2 / 8 from its arc.
  const double step = std::sqrt(8.0 * tolerance_px / std::max(radius, tolerance_px));
  const std::size_t steps = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(span / step)), 8, kMaxSteps);
  const std::size_t count = outline.closed ? steps : steps + 1;  // a closed outline does not repeat its start
  outline.points.reserve(count + 1);
  for (std::size_t i = 0; i < count; ++i) {
    const double angle = from + span * static_cast<double>(i) / static_cast<double>(steps);
    outline.points.push_back({center.x + radius * std::cos(angle), center.y + radius * std::sin(angle)});
  }
  return outline;
}

}  // namespace meshstep::scene::detail
