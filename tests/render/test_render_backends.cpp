// EGL and OSMesa are both Mesa's llvmpipe: the same scene must give the same picture on both
// (within the tolerance golden-image tests use: 5 per channel on at most 0.1% of pixels).
#include <gtest/gtest.h>

#include <optional>

#include "render_test_support.hpp"

namespace meshstep::render::testing {
namespace {

// The test scene with a label and a legend too, drawn on one backend; nullopt (and the reason
// in `why`) when that backend has no context here.
std::optional<scene::Image> draw_on(Backend backend, int samples, std::string& why) {
  std::unique_ptr<GlContext> context;
  try {
    context = make_offscreen_context(backend);
  } catch (const GlUnavailable& e) {
    why = e.what();
    return std::nullopt;
  }
  scene::Scene s = test_scene();
  s.labels.push_back({{70, 60}, "Lepp 1", kText, 14.0f, 4.0f, 0.0f});
  scene::Legend legend;
  legend.title = "quality";
  legend.colors = {{68, 1, 84, 255}, {33, 145, 140, 255}, {253, 231, 37, 255}};
  legend.ticks = {{0.0, "0"}, {0.5, "0.5"}, {1.0, "1"}};
  s.legend = legend;
  Renderer renderer;
  renderer.render(s, test_camera(800, 400), samples);
  return renderer.read_pixels();
}

void expect_same_picture(int samples) {
  std::string why;
  const std::optional<scene::Image> egl = draw_on(Backend::egl, samples, why);
  if (!egl) GTEST_SKIP() << why;
  const std::optional<scene::Image> osmesa = draw_on(Backend::osmesa, samples, why);
  if (!osmesa) GTEST_SKIP() << why;
  const scene::ImageDiff diff = scene::compare_images(*egl, *osmesa, 5);
  ASSERT_TRUE(diff.same_size);
  const std::size_t pixels = static_cast<std::size_t>(egl->width) * egl->height;
  EXPECT_LE(diff.differing_pixels, pixels / 1000)
      << "EGL " << save_for_inspection(*egl, "egl") << ", OSMesa " << save_for_inspection(*osmesa, "osmesa")
      << ", where they differ " << save_for_inspection(diff.picture, "egl_osmesa_diff");
}

TEST(RenderBackends, EglAndOsmesaDrawTheSamePicture) { expect_same_picture(1); }
TEST(RenderBackends, EglAndOsmesaDrawTheSameMultisampledPicture) { expect_same_picture(4); }

}  // namespace
}  // namespace meshstep::render::testing
