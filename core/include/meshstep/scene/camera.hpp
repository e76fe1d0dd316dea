// The camera: which world window a picture of width x height pixels shows.
//
// Screen coordinates are pixels with the origin at the top-left corner and y down (as in
// images and SVG); world y points up. The camera keeps the aspect ratio: a pixel is square
// in world units. It fits a box with a margin, or shows a world window you give (grown in
// one direction to the picture's aspect), and it zooms at a point and pans (the viewer).
#pragma once

#include "meshstep/geometry/point.hpp"

namespace meshstep::scene {

// Room kept free on each side of the picture when fitting, in pixels (a caption band on
// top, a legend on the right).
struct Margins {
  double left = 24.0, top = 24.0, right = 24.0, bottom = 24.0;
};

class Camera {
 public:
  Camera() = default;
  Camera(Point center, double pixels_per_unit, int width, int height)
      : center_(center), scale_(pixels_per_unit), width_(width), height_(height) {}

  // The box, centred, as large as fits inside the picture less `margin_px` on every side.
  // An empty or degenerate box gets a unit-sized window around its centre.
  static Camera fit(const BBox& box, int width, int height, double margin_px = 24.0) {
    return fit(box, width, height, Margins{margin_px, margin_px, margin_px, margin_px});
  }
  // The box, centred in what the margins leave free.
  static Camera fit(const BBox& box, int width, int height, const Margins& margins);
  // Shows at least the world window [x0,x1] x [y0,y1]: the window is centred, and the
  // direction with room to spare shows more.
  static Camera window(const BBox& world_window, int width, int height) {
    return fit(world_window, width, height, Margins{0.0, 0.0, 0.0, 0.0});
  }

  Point to_screen(const Point& world) const {
    return {(world.x - center_.x) * scale_ + 0.5 * width_, 0.5 * height_ - (world.y - center_.y) * scale_};
  }
  Point to_world(const Point& screen) const {
    return {center_.x + (screen.x - 0.5 * width_) / scale_, center_.y - (screen.y - 0.5 * height_) / scale_};
  }

  // Zooms by `factor` (> 1: closer) keeping the world point under `screen` in place.
  void zoom_at(const Point& screen, double factor);
  // Moves the picture by (dx, dy) pixels: the world follows the pointer.
  void pan(double dx_px, double dy_px);
  void resize(int width, int height) {
    width_ = width;
    height_ = height;
  }

  Point center() const { return center_; }
  double pixels_per_unit() const { return scale_; }
  int width() const { return width_; }
  int height() const { return height_; }
  // The world window the picture shows.
  BBox visible() const;

 private:
  Point center_{0.0, 0.0};
  double scale_ = 1.0;
  int width_ = 1, height_ = 1;
};

}  // namespace meshstep::scene
