// World coordinates, made fit for the GPU's floats.
//
// A world may be anywhere from 1e-300 to 1e300 across, and far from the origin. Points go to
// the GPU as "local" floats: (p - origin) * scale, computed in double, with an origin near
// what is looked at and a scale that makes it about one unit across. The camera's mapping
// from local units to pixels is computed in double as well and handed over as a float scale
// and offset (shaders/common.glsl, local_to_pixels). The frame changes only when the camera
// moves so far (a deep zoom, a long pan) that float rounding would show: then the buffers are
// filled again; an ordinary zoom or pan only changes the uniforms.
#pragma once

#include <array>

#include "meshstep/scene/camera.hpp"

namespace meshstep::render {

struct WorldFrame {
  Point origin{0.0, 0.0};
  double scale = 1.0;  // local units per world unit

  // The local coordinates of a world point, clamped to +-1e30 (never infinite or NaN).
  std::array<float, 2> to_local(const Point& world) const;
  float to_local_length(double world_length) const;
  friend bool operator==(const WorldFrame&, const WorldFrame&) = default;
};

// pixel = local * scale + offset, for each axis (y down: scale_y < 0).
struct LocalToPixels {
  std::array<float, 2> scale{1.0f, -1.0f};
  std::array<float, 2> offset{0.0f, 0.0f};
};
LocalToPixels local_to_pixels(const WorldFrame& frame, const scene::Camera& camera);

// How far, in pixels, float rounding of local coordinates can move what the camera shows.
double rounding_error_px(const WorldFrame& frame, const scene::Camera& camera);

// The frame to draw with: `current` while its rounding stays invisible, else one centred on
// the scene's bounds (when that is good enough for this camera), else one centred on the
// camera.
WorldFrame choose_frame(const BBox& bounds, const scene::Camera& camera, const WorldFrame* current);

}  // namespace meshstep::render
