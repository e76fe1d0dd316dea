// A triangle surface in 3D as a scene (scene/surface_view.hpp): the projection checked
// against hand-computed values, the painter's order, the shading, the height colours, the
// top view, and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "meshstep/scene/colormap.hpp"
#include "meshstep/scene/surface_view.hpp"

namespace meshstep::scene {
namespace {

using Tri = std::array<std::uint32_t, 3>;

Tri sorted(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
}

// The index in the scene of the surface's triangle with these vertices.
std::size_t find_triangle(const Scene& s, Tri t) {
  for (std::size_t i = 0; i < s.mesh.triangles.size(); ++i)
    if (sorted(s.mesh.triangles[i]) == sorted(t)) return i;
  ADD_FAILURE() << "triangle not in the scene";
  return SIZE_MAX;
}

int lightness(Rgba c) { return c.r + c.g + c.b; }

TEST(SurfaceScene, ProjectsOrthographicallyAsComputedByHand) {
  // Azimuth 0, elevation 0: the camera on +x looking toward -x; the screen's right is +y,
  // up is +z. Azimuth 90, elevation 45: the camera on (0, 1, 1)/sqrt 2; right is -x, up is
  // (0, -1, 1)/sqrt 2.
  io::Surface tri{{{1, 2, 3}, {-1, 0, 2}, {0, -3, 1}}, {{0, 1, 2}}};
  SurfaceView side;
  side.azimuth_deg = 0.0;
  side.elevation_deg = 0.0;
  const Scene a = surface_scene(tri, side, Theme::light);
  ASSERT_EQ(a.mesh.points.size(), 3u);
  EXPECT_NEAR(a.mesh.points[0].x, 2.0, 1e-12);
  EXPECT_NEAR(a.mesh.points[0].y, 3.0, 1e-12);
  EXPECT_NEAR(a.mesh.points[2].x, -3.0, 1e-12);
  EXPECT_NEAR(a.mesh.points[2].y, 1.0, 1e-12);

  SurfaceView oblique;
  oblique.azimuth_deg = 90.0;
  oblique.elevation_deg = 45.0;
  oblique.z_scale = 2.0;
  const Scene b = surface_scene(tri, oblique, Theme::light);
  const double r = std::numbers::sqrt2 / 2.0;
  // (1, 2, 3) with z doubled: (1, 2, 6). right = (-1, 0, 0): -1; up: (-2 + 6) r.
  EXPECT_NEAR(b.mesh.points[0].x, -1.0, 1e-12);
  EXPECT_NEAR(b.mesh.points[0].y, 4.0 * r, 1e-12);
  // (-1, 0, 4): 1; (0 + 4) r.
  EXPECT_NEAR(b.mesh.points[1].x, 1.0, 1e-12);
  EXPECT_NEAR(b.mesh.points[1].y, 4.0 * r, 1e-12);
  // (0, -3, 2): 0; (3 + 2) r.
  EXPECT_NEAR(b.mesh.points[2].x, 0.0, 1e-12);
  EXPECT_NEAR(b.mesh.points[2].y, 5.0 * r, 1e-12);
  EXPECT_TRUE(b.mesh.painter_order);
  // Counterclockwise on screen, whichever way the triangle faces.
  const auto& t = b.mesh.triangles.at(0);
  const Point &p = b.mesh.points[t[0]], &q = b.mesh.points[t[1]], &s = b.mesh.points[t[2]];
  EXPECT_GT((q.x - p.x) * (s.y - p.y) - (q.y - p.y) * (s.x - p.x), 0.0);
}

TEST(SurfaceScene, DrawsTheFartherTriangleFirst) {
  // Two parallel horizontal triangles, one at x near 5 and one near -5; the camera on +x
  // (azimuth 0, elevation 20) sees the one at -5 behind. Listed nearest first.
  io::Surface two{{{5, 0, 0}, {6, 1, 0}, {5, 1, 0}, {-5, 0, 0}, {-4, 1, 0}, {-5, 1, 0}}, {{0, 1, 2}, {3, 4, 5}}};
  SurfaceView v;
  v.azimuth_deg = 0.0;
  v.elevation_deg = 20.0;
  const Scene s = surface_scene(two, v, Theme::light);
  ASSERT_EQ(s.mesh.triangles.size(), 2u);
  EXPECT_EQ(sorted(s.mesh.triangles[0]), (Tri{3, 4, 5}));
  EXPECT_EQ(sorted(s.mesh.triangles[1]), (Tri{0, 1, 2}));
  // From the other side, the other way round.
  v.azimuth_deg = 180.0;
  const Scene back = surface_scene(two, v, Theme::light);
  EXPECT_EQ(sorted(back.mesh.triangles[0]), (Tri{0, 1, 2}));
}

// A square pyramid: apex over the centre of a square base, four faces, outward normals.
io::Surface pyramid(double height) {
  return {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, height}},
          {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}};
}

TEST(SurfaceScene, FacesTowardTheLightAreLighter) {
  SurfaceView v;
  v.azimuth_deg = -90.0;  // from -y
  v.elevation_deg = 60.0;
  v.light = Point3{-1.0, 0.0, 0.5};  // from -x (and above)
  const io::Surface p = pyramid(1.0);
  const Scene s = surface_scene(p, v, Theme::light);
  // Face 3 (3, 0, 4) faces -x, toward the light; face 1 (1, 2, 4) faces +x, away. Both
  // have the same heights, so the same colour before shading.
  const Rgba toward = s.mesh.fill.at(find_triangle(s, {3, 0, 4}));
  const Rgba away = s.mesh.fill.at(find_triangle(s, {1, 2, 4}));
  EXPECT_GT(lightness(toward), lightness(away) + 60);
  // Ambient light: even the face turned away is not black.
  EXPECT_GT(lightness(away), 30);
  // The light from the mirrored side lights the mirrored face exactly as much.
  v.light = Point3{1.0, 0.0, 0.5};
  const Scene mirrored = surface_scene(p, v, Theme::light);
  EXPECT_EQ(mirrored.mesh.fill.at(find_triangle(mirrored, {1, 2, 4})), toward);
  // Two-sided: a face listed the other way round (its normal pointing away from the
  // camera) is lit as if it faced the camera.
  io::Surface flipped = p;
  for (auto& t : flipped.triangles) std::swap(t[0], t[1]);
  v.light = Point3{-1.0, 0.0, 0.5};
  const Scene f = surface_scene(flipped, v, Theme::light);
  EXPECT_EQ(f.mesh.fill.at(find_triangle(f, {3, 0, 4})), toward);
  EXPECT_EQ(f.mesh.fill.at(find_triangle(f, {1, 2, 4})), away);
}

TEST(SurfaceScene, ColoursFollowHeight) {
  // A flat strip of triangles rising in steps along x, lit alike (the light straight down
  // the flat normal, the camera straight above): colour only from height.
  io::Surface steps;
  for (int i = 0; i < 4; ++i) {
    const auto b = static_cast<std::uint32_t>(steps.vertices.size());
    const double z = i;
    steps.vertices.insert(steps.vertices.end(), {{2.0 * i, 0, z}, {2.0 * i + 1, 0, z}, {2.0 * i, 1, z}});
    steps.triangles.push_back({b, b + 1, b + 2});
  }
  SurfaceView top;
  top.elevation_deg = 90.0;
  top.light = Point3{0, 0, 1};
  const Scene s = surface_scene(steps, top, Theme::light);
  ASSERT_EQ(s.mesh.values.size(), 4u);
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::size_t at = find_triangle(s, {3 * i, 3 * i + 1, 3 * i + 2});
    EXPECT_DOUBLE_EQ(s.mesh.values.at(at), i);
    // Lit full on: exactly the map's colour at the height's place in the range 0..3.
    EXPECT_EQ(s.mesh.fill.at(at), viridis()(i / 3.0)) << i;
  }
  EXPECT_EQ(s.mesh.fill.at(find_triangle(s, {9, 10, 11})), viridis()(1.0));  // the map's high end
  ASSERT_TRUE(s.legend);
  EXPECT_EQ(s.legend->title, "height");
  EXPECT_EQ(s.legend->ticks.front().text, "0");
  EXPECT_EQ(s.legend->ticks.back().text, "3");
  EXPECT_DOUBLE_EQ(s.legend->ticks.back().at, 1.0);
}

TEST(SurfaceScene, TopViewIsThePlainLayoutUpToRotation) {
  const io::Surface p = pyramid(2.0);
  SurfaceView top;
  top.elevation_deg = 90.0;
  top.azimuth_deg = -90.0;
  const Scene s = surface_scene(p, top, Theme::light);
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    EXPECT_NEAR(s.mesh.points[i].x, p.vertices[i].x, 1e-12);
    EXPECT_NEAR(s.mesh.points[i].y, p.vertices[i].y, 1e-12);
  }
  // Another azimuth turns the picture by azimuth + 90 degrees, clockwise.
  top.azimuth_deg = -30.0;
  const Scene turned = surface_scene(p, top, Theme::light);
  const double a = 60.0 * std::numbers::pi / 180.0;
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    const double x = p.vertices[i].x, y = p.vertices[i].y;
    EXPECT_NEAR(turned.mesh.points[i].x, std::cos(a) * x + std::sin(a) * y, 1e-12);
    EXPECT_NEAR(turned.mesh.points[i].y, -std::sin(a) * x + std::cos(a) * y, 1e-12);
  }
}

TEST(SurfaceScene, IsDeterministicAndSaysWhatItShows) {
  const io::Surface p = pyramid(1.5);
  const SurfaceView v;
  const Scene a = surface_scene(p, v, Theme::dark, "pyramid.obj");
  const Scene b = surface_scene(p, v, Theme::dark, "pyramid.obj");
  EXPECT_EQ(a.mesh.points, b.mesh.points);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.fill, b.mesh.fill);
  EXPECT_EQ(a.mesh.values, b.mesh.values);
  EXPECT_EQ(a.caption, "pyramid.obj \u00B7 5 vertices, 4 triangles \u00B7 azimuth -60\u00B0, elevation 35\u00B0");
  EXPECT_EQ(a.background, b.background);
  EXPECT_FALSE(a.bounds.empty());
  // Ties in depth keep the surface's order: seen from +x (azimuth 0, elevation 0) the
  // depth is x, the same for two triangles in the plane x = 0 at different heights.
  io::Surface tie{{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 5}, {0, 1, 5}, {0, 0, 6}}, {{3, 4, 5}, {0, 1, 2}}};
  SurfaceView side;
  side.azimuth_deg = 0.0;
  side.elevation_deg = 0.0;
  const Scene t = surface_scene(tie, side, Theme::light);
  ASSERT_EQ(t.mesh.values.size(), 2u);
  EXPECT_DOUBLE_EQ(t.mesh.values[0], 16.0 / 3.0);
  std::swap(tie.triangles[0], tie.triangles[1]);
  const Scene swapped = surface_scene(tie, side, Theme::light);
  EXPECT_DOUBLE_EQ(swapped.mesh.values[0], 1.0 / 3.0);
}

}  // namespace
}  // namespace meshstep::scene
