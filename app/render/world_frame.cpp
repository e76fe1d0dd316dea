#include "world_frame.hpp"

#include <algorithm>
#include <cmath>

namespace meshstep::render {

namespace {

constexpr double kLocalLimit = 1e30;
// Rounding below a sixteenth of a pixel does not show.
constexpr double kInvisibleError = 1.0 / 16.0;
// The spacing of floats near 1, relative: 2^-23.
constexpr double kFloatEpsilon = 1.0 / 8388608.0;

float clamped(double v) {
  if (std::isnan(v)) return 0.0f;
  return static_cast<float>(std::clamp(v, -kLocalLimit, kLocalLimit));
}

}  // namespace

std::array<float, 2> WorldFrame::to_local(const Point& world) const {
  return {clamped((world.x - origin.x) * scale), clamped((world.y - origin.y) * scale)};
}

float WorldFrame::to_local_length(double world_length) const { return clamped(world_length * scale); }

LocalToPixels local_to_pixels(const WorldFrame& frame, const scene::Camera& camera) {
  // pixel.x = (world.x - center.x) * k + width / 2, world = origin + local / scale.
  const double k = camera.pixels_per_unit();
  const double pixels_per_local = k / frame.scale;
  const Point c = camera.center();
  LocalToPixels out;
  out.scale = {static_cast<float>(pixels_per_local), static_cast<float>(-pixels_per_local)};
  out.offset = {static_cast<float>((frame.origin.x - c.x) * k + 0.5 * camera.width()),
                static_cast<float>(0.5 * camera.height() - (frame.origin.y - c.y) * k)};
  return out;
}

double rounding_error_px(const WorldFrame& frame, const scene::Camera& camera) {
  // The largest local coordinate on screen is about |local centre| + half the view; floats
  // near it are spaced epsilon times that, which the camera magnifies by pixels_per_local.
  const double pixels_per_local = camera.pixels_per_unit() / frame.scale;
  const Point c = camera.center();
  const double center_px = std::max(std::abs(c.x - frame.origin.x), std::abs(c.y - frame.origin.y)) *
                           camera.pixels_per_unit();
  const double half_view_px = 0.5 * std::max(camera.width(), camera.height());
  const double error = kFloatEpsilon * (center_px + half_view_px);
  // A frame whose pixels per local unit do not fit a float is no good at all.
  return std::isfinite(error) && std::isfinite(static_cast<float>(pixels_per_local)) && pixels_per_local > 0.0
             ? error
             : INFINITY;
}

WorldFrame choose_frame(const BBox& bounds, const scene::Camera& camera, const WorldFrame* current) {
  if (current && rounding_error_px(*current, camera) <= kInvisibleError) return *current;
  if (!bounds.empty()) {
    const double extent = std::max(bounds.hi.x - bounds.lo.x, bounds.hi.y - bounds.lo.y);
    const Point middle{0.5 * bounds.lo.x + 0.5 * bounds.hi.x, 0.5 * bounds.lo.y + 0.5 * bounds.hi.y};
    if (extent > 0.0 && std::isfinite(extent) && std::isfinite(1.0 / extent)) {
      const WorldFrame of_bounds{middle, 1.0 / extent};
      if (rounding_error_px(of_bounds, camera) <= kInvisibleError) return of_bounds;
    }
  }
  // Centred on the camera, the visible window about 2 local units across.
  const double half_view_px = 0.5 * std::max(camera.width(), camera.height());
  return WorldFrame{camera.center(), camera.pixels_per_unit() / std::max(half_view_px, 1.0)};
}

}  // namespace meshstep::render

