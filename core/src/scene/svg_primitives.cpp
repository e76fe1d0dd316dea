// Triangles and segments into path data, with the visibility test and the guard-box cut
// every part of the SVG shares; and unique element ids.
#include <algorithm>
#include <string>

#include "scene/svg_parts.hpp"

namespace meshstep::scene::detail {

std::string IdRegistry::unique(std::string_view base) {
  std::string id(base);
  for (int n = 2; used_.count(id) != 0; ++n) id = std::string(base) + "-" + std::to_string(n);
  used_.insert(id);
  return id;
}

void TriangleWriter::add(Point a, Point b, Point q) {
  if (!finite(a) || !finite(b) || !finite(q)) return;
  const Point lo{std::min({a.x, b.x, q.x}), std::min({a.y, b.y, q.y})};
  const Point hi{std::max({a.x, b.x, q.x}), std::max({a.y, b.y, q.y})};
  if (!c_.view.grown(pad_).overlaps(lo, hi)) return;
  const double turn = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
  if (turn == 0.0) return;  // no area
  // Counterclockwise in the world is clockwise on screen (y down), turn < 0: keep every
  // triangle that way.
  if (turn > 0.0) std::swap(b, q);

  if (c_.guard.contains(lo) && c_.guard.contains(hi)) {
    path_.move_to(a);
    path_.line_to(b);
    path_.line_to(q);
    path_.close();
    return;
  }
  polygon_.assign({a, b, q});
  clip_polygon(polygon_, c_.guard, clipped_);
  if (clipped_.empty()) return;
  path_.move_to(clipped_.front());
  for (std::size_t i = 1; i < clipped_.size(); ++i) path_.line_to(clipped_[i]);
  path_.close();
}

void SegmentWriter::add(Point a, Point b, bool joins) {
  const bool was_down = pen_down_;
  pen_down_ = false;
  if (!finite(a) || !finite(b)) return;
  const Point lo{std::min(a.x, b.x), std::min(a.y, b.y)}, hi{std::max(a.x, b.x), std::max(a.y, b.y)};
  if (!c_.view.grown(pad_).overlaps(lo, hi)) return;
  if (c_.guard.contains(a) && c_.guard.contains(b)) {
    if (!(joins && was_down)) path_.move_to(a);
    path_.line_to(b);
    pen_down_ = true;
    return;
  }
  Point from = a, to = b;
  if (!clip_segment(from, to, c_.guard)) return;
  path_.move_to(from);
  path_.line_to(to);
  pen_down_ = to == b;  // the pen is still at b when the cut left that end alone
}

}  // namespace meshstep::scene::detail
