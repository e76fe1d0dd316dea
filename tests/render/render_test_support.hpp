// What the renderer tests share: a small scene built by hand whose every pixel of interest is
// known, pixel helpers, and a fixture that runs a test on one off-screen backend (skipped,
// with the reason, when that backend cannot make a context here).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <ostream>
#include <string>

#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/image.hpp"
#include "meshstep/scene/scene.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"

namespace meshstep::scene {
inline void PrintTo(const Rgba& c, std::ostream* os) {
  *os << "rgba(" << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ", " << int(c.a) << ")";
}
}  // namespace meshstep::scene

namespace meshstep::render {
inline void PrintTo(Backend b, std::ostream* os) { *os << name(b); }
}  // namespace meshstep::render

namespace meshstep::render::testing {

using scene::Rgba;

inline constexpr Rgba kBackground{250, 250, 250, 255};
inline constexpr Rgba kRed{220, 40, 40, 255};
inline constexpr Rgba kGreen{40, 180, 60, 255};
inline constexpr Rgba kEdge{30, 30, 30, 255};
inline constexpr Rgba kBlue{20, 40, 200, 255};
inline constexpr Rgba kPurple{150, 30, 160, 255};
inline constexpr Rgba kRing{0, 0, 0, 255};
inline constexpr Rgba kMarker{200, 120, 0, 255};
inline constexpr Rgba kText{20, 20, 20, 255};

// The test picture: 400 x 400 pixels showing the world square [0, 100]^2, 4 pixels a unit,
// so that world (x, y) is pixel (4x, 400 - 4y).
//   mesh: T0 = (10,10) (50,10) (10,50) red, T1 = (50,10) (50,50) (10,50) green; edges 1 px
//         of kEdge. Centroids: T0 pixel (93, 306), T1 pixel (146, 253); their shared edge
//         passes through pixel (120, 280).
//   segments: a solid blue line from (10,80) to (90,80), 6 px wide: pixel rows 77..82;
//             a dashed purple line from (15,90) to (85,90), 4 px wide: around pixel row 40.
//   overlay: an unfilled black circle round (70,40), radius 10 (40 px), 3 px stroke: the
//            centre is pixel (280, 240), the ring crosses pixel (319, 240).
//   vertices: an orange disc marker, 10 px, at (80,85): pixel (320, 60), near the top.
//   caption: "meshstep renderer test", in the band across the top 30 rows.
inline constexpr int kSize = 400;
scene::Scene test_scene();
scene::Camera test_camera(int width = kSize, int height = kSize);

inline Rgba pixel(const scene::Image& image, int x, int y) {
  const std::uint8_t* p = image.row(y) + 4 * x;
  return {p[0], p[1], p[2], p[3]};
}
// Every channel within `tolerance`.
inline bool near(const Rgba& a, const Rgba& b, int tolerance = 3) {
  const auto close = [&](int u, int v) { return std::abs(u - v) <= tolerance; };
  return close(a.r, b.r) && close(a.g, b.g) && close(a.b, b.b) && close(a.a, b.a);
}
inline int luminance(const Rgba& c) { return (299 * c.r + 587 * c.g + 114 * c.b) / 1000; }

// Pixels in [x0, x1) x [y0, y1) darker than `below`.
int dark_pixels(const scene::Image& image, int x0, int y0, int x1, int y1, int below = 100);

// Writes the image beside the test's other outputs for a look when a test fails; returns
// the path.
std::string save_for_inspection(const scene::Image& image, const std::string& name);

const char* backend_label(Backend backend);

class RenderTest : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override;
  void TearDown() override;
  // The scene drawn and read back.
  scene::Image draw(const scene::Scene& scene, const scene::Camera& camera, int samples = 1);

  std::unique_ptr<GlContext> context_;
  std::unique_ptr<Renderer> renderer_;
};

}  // namespace meshstep::render::testing
