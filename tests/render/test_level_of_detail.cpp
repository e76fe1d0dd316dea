// The level of detail (render/mesh_raster.hpp): a dense mesh drawn approximately must give
// the exact picture within the golden tolerance (5 per channel on at most 0.1% of the
// pixels), whether its triangles are all small (the CPU finds them all) or mixed with
// larger ones (GL draws those).
#include <gtest/gtest.h>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/layout.hpp"
#include "render_test_support.hpp"

namespace meshstep::render::testing {
namespace {

// A Delaunay mesh of uniform points in the unit square, coloured by smallest angle: a fresh
// colour almost every triangle, so a pixel given to the wrong triangle shows.
scene::Scene dense_scene(std::size_t points) {
  Pslg input;
  std::uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (std::size_t i = 0; i < points; ++i) input.points.push_back({next(), next()});
  scene::SceneOptions options;
  options.color_by = scene::ColorBy::angle;
  return scene::build_scene(triangulate(std::move(input)), options);
}

void expect_within_golden_tolerance(const scene::Image& exact, const scene::Image& approximate, const char* name) {
  const scene::ImageDiff diff = scene::compare_images(exact, approximate, 5);
  ASSERT_TRUE(diff.same_size);
  const double allowed = 0.001 * exact.width * exact.height;
  EXPECT_LE(static_cast<double>(diff.differing_pixels), allowed)
      << "largest difference " << diff.max_channel_delta << "; see " << save_for_inspection(approximate, name)
      << " against " << save_for_inspection(exact, std::string(name) + "_exact");
}

TEST_P(RenderTest, LevelOfDetailOfSmallTrianglesIsTheExactPicture) {
  const scene::Scene s = dense_scene(100000);  // about 200,000 triangles of 2-3 pixels each
  const scene::Camera camera = scene::fit_scene(s, 1280, 720);
  const scene::Image exact = draw(s, camera);
  renderer_->render(s, camera, 1, Detail::approximate);
  const scene::Image approximate = renderer_->read_pixels();
  EXPECT_EQ(renderer_->counters().approximate_frames, 1u);
  EXPECT_GT(renderer_->counters().raster_triangles, 190000u);  // all but a few found on the CPU
  expect_within_golden_tolerance(exact, approximate, "lod_small");
  // And back: the next exact frame is the exact picture (the mesh's buffers are still good).
  const scene::Image again = draw(s, camera);
  EXPECT_EQ(scene::compare_images(exact, again, 0).differing_pixels, 0u);
}

TEST_P(RenderTest, LevelOfDetailMixesCpuAndGlTriangles) {
  // Zoomed in so that some triangles span more than MeshRaster::kMaxSpan pixels and go to GL.
  const scene::Scene s = dense_scene(3000);
  const scene::Camera camera(Point{0.5, 0.5}, 2400.0, 800, 600);  // triangles of 5-40 pixels
  const scene::Image exact = draw(s, camera);
  renderer_->render(s, camera, 1, Detail::approximate);
  const scene::Image approximate = renderer_->read_pixels();
  const std::size_t on_cpu = renderer_->counters().raster_triangles;
  EXPECT_GT(on_cpu, 0u);
  EXPECT_LT(on_cpu, s.mesh.triangles.size());
  expect_within_golden_tolerance(exact, approximate, "lod_mixed");
}

TEST_P(RenderTest, LevelOfDetailStepsAsideWhereItCannotApply) {
  // The fill off: the exact pass draws it (the raster only replaces an opaque fill).
  scene::Scene s = dense_scene(2000);
  s.visible.set(scene::Layer::fill, false);
  const scene::Camera camera = scene::fit_scene(s, 400, 300);
  renderer_->render(s, camera, 1, Detail::approximate);
  EXPECT_EQ(renderer_->counters().approximate_frames, 0u);
}

}  // namespace
}  // namespace meshstep::render::testing
