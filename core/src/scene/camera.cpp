#include "meshstep/scene/camera.hpp"

#include <algorithm>
#include <cmath>

namespace meshstep::scene {

namespace {

// A box with some extent in both directions: an empty box becomes the unit square round
// the origin, a point or a line gets the extent of its longer side (or 1).
BBox with_extent(const BBox& box) {
  if (box.empty()) return BBox{{-0.5, -0.5}, {0.5, 0.5}};
  const double w = box.hi.x - box.lo.x, h = box.hi.y - box.lo.y;
  const double side = std::max({w, h, 0.0}) > 0.0 && std::isfinite(std::max(w, h)) ? std::max(w, h) : 1.0;
  BBox out = box;
  if (!(w > 0.0)) out.lo.x -= 0.5 * side, out.hi.x += 0.5 * side;
  if (!(h > 0.0)) out.lo.y -= 0.5 * side, out.hi.y += 0.5 * side;
  return out;
}

Point middle(const BBox& b) { return {0.5 * b.lo.x + 0.5 * b.hi.x, 0.5 * b.lo.y + 0.5 * b.hi.y}; }

}  // namespace

Camera Camera::fit(const BBox& box, int width, int height, const Margins& m) {
  const BBox b = with_extent(box);
  const double room_x = std::max(1.0, width - m.left - m.right), room_y = std::max(1.0, height - m.top - m.bottom);
  const double scale = std::min(room_x / (b.hi.x - b.lo.x), room_y / (b.hi.y - b.lo.y));
  // The box's centre goes to the centre of the free area, which is off the picture's centre
  // by half the difference of opposite margins.
  const Point c = middle(b);
  const Point center{c.x + 0.5 * (m.right - m.left) / scale, c.y + 0.5 * (m.top - m.bottom) / scale};
  return Camera(center, scale, width, height);
}

void Camera::zoom_at(const Point& screen, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor)) return;
  const Point anchor = to_world(screen);
  scale_ *= factor;
  // Move the centre so that `anchor` is under `screen` again.
  const Point moved = to_world(screen);
  center_.x += anchor.x - moved.x;
  center_.y += anchor.y - moved.y;
}

void Camera::pan(double dx_px, double dy_px) {
  center_.x -= dx_px / scale_;
  center_.y += dy_px / scale_;
}

BBox Camera::visible() const {
  BBox b;
  b.add(to_world({0.0, 0.0}));
  b.add(to_world({static_cast<double>(width_), static_cast<double>(height_)}));
  return b;
}

}  // namespace meshstep::scene
