// World coordinates to GPU floats (render/world_frame.hpp): no GL needed.
#include <gtest/gtest.h>

#include <cmath>

#include "render/world_frame.hpp"

namespace meshstep::render {
namespace {

// Where a world point lands on screen through the frame and the float transform, as the GPU
// computes it (in float).
Point through_gpu(const WorldFrame& frame, const scene::Camera& camera, const Point& world) {
  const auto local = frame.to_local(world);
  const LocalToPixels t = local_to_pixels(frame, camera);
  return {local[0] * t.scale[0] + t.offset[0], local[1] * t.scale[1] + t.offset[1]};
}

void expect_close_to_camera(const WorldFrame& frame, const scene::Camera& camera, const Point& world, double px) {
  const Point exact = camera.to_screen(world), gpu = through_gpu(frame, camera, world);
  EXPECT_NEAR(gpu.x, exact.x, px);
  EXPECT_NEAR(gpu.y, exact.y, px);
}

TEST(WorldFrame, MapsLikeTheCameraAtEveryScale) {
  for (const double unit : {1e-300, 1e-20, 1.0, 1e20, 1e300}) {
    const BBox bounds{{-3 * unit, 2 * unit}, {5 * unit, 9 * unit}};
    const scene::Camera camera = scene::Camera::fit(bounds, 800, 600);
    const WorldFrame frame = choose_frame(bounds, camera, nullptr);
    for (const Point p : {bounds.lo, bounds.hi, Point{unit, 4 * unit}})
      expect_close_to_camera(frame, camera, p, 1e-3);
  }
}

TEST(WorldFrame, FarFromTheOriginStaysPrecise) {
  const BBox bounds{{1e12, 1e12}, {1e12 + 1.0, 1e12 + 1.0}};
  const scene::Camera camera = scene::Camera::fit(bounds, 800, 800);
  const WorldFrame frame = choose_frame(bounds, camera, nullptr);
  expect_close_to_camera(frame, camera, {1e12 + 0.123456, 1e12 + 0.654321}, 1e-3);
}

TEST(WorldFrame, KeptWhileTheCameraPansAndZoomsModerately) {
  const BBox bounds{{0, 0}, {10, 10}};
  scene::Camera camera = scene::Camera::fit(bounds, 800, 800);
  const WorldFrame frame = choose_frame(bounds, camera, nullptr);
  camera.zoom_at({100, 100}, 1000.0);
  camera.pan(300, -200);
  EXPECT_EQ(choose_frame(bounds, camera, &frame), frame);
}

TEST(WorldFrame, RecentredForADeepZoom) {
  const BBox bounds{{0, 0}, {10, 10}};
  scene::Camera camera = scene::Camera::fit(bounds, 800, 800);
  const WorldFrame frame = choose_frame(bounds, camera, nullptr);
  camera.zoom_at({123, 456}, 1e9);
  const WorldFrame deep = choose_frame(bounds, camera, &frame);
  EXPECT_NE(deep, frame);
  EXPECT_LE(rounding_error_px(deep, camera), 1.0 / 16);
  const Point near_center = camera.to_world({400.25, 399.75});
  expect_close_to_camera(deep, camera, near_center, 1e-3);
}

TEST(WorldFrame, ClampsWhatFloatsCannotHold) {
  const WorldFrame frame{{0, 0}, 1e10};
  const auto local = frame.to_local({1e300, -1e300});
  EXPECT_TRUE(std::isfinite(local[0]));
  EXPECT_TRUE(std::isfinite(local[1]));
  EXPECT_GT(local[0], 0.0f);
  EXPECT_LT(local[1], 0.0f);
  const auto nan = frame.to_local({std::nan(""), 1.0});
  EXPECT_EQ(nan[0], 0.0f);
}

}  // namespace
}  // namespace meshstep::render
