// The renderer's picture of a hand-made scene, pixel by pixel, on each off-screen backend.
#include <gtest/gtest.h>

#include "render_test_support.hpp"

namespace meshstep::render::testing {
namespace {

using scene::Layer;

TEST_P(RenderTest, BackgroundFillsTheCorners) {
  const scene::Image image = draw(test_scene(), test_camera());
  ASSERT_EQ(image.width, kSize);
  ASSERT_EQ(image.height, kSize);
  ASSERT_EQ(image.rgba.size(), std::size_t{kSize} * kSize * 4);
  EXPECT_PRED3(near, pixel(image, kSize - 1, kSize - 1), kBackground, 0);
  EXPECT_PRED3(near, pixel(image, 0, kSize - 1), kBackground, 0);
}

TEST_P(RenderTest, EachTriangleShowsItsFillColourAtItsCentroid) {
  const scene::Image image = draw(test_scene(), test_camera());
  EXPECT_PRED3(near, pixel(image, 93, 306), kRed, 2);
  EXPECT_PRED3(near, pixel(image, 146, 253), kGreen, 2);
}

TEST_P(RenderTest, SharedEdgeIsDrawnDark) {
  const scene::Image image = draw(test_scene(), test_camera());
  EXPECT_LT(luminance(pixel(image, 120, 280)), 100) << save_for_inspection(image, "edge");
}

TEST_P(RenderTest, ThickLineCoversItsWidthAndNoMore) {
  const scene::Image image = draw(test_scene(), test_camera());
  // 6 px wide, centred between rows 79 and 80: rows 77..82.
  for (int y = 77; y <= 82; ++y) EXPECT_PRED3(near, pixel(image, 200, y), kBlue, 2) << "row " << y;
  EXPECT_PRED3(near, pixel(image, 200, 75), kBackground, 0);
  EXPECT_PRED3(near, pixel(image, 200, 84), kBackground, 0);
  // Round caps: the line ends half its width past its end point (x = 40), no further.
  EXPECT_PRED3(near, pixel(image, 38, 79), kBlue, 2);
  EXPECT_PRED3(near, pixel(image, 34, 79), kBackground, 0);
}

TEST_P(RenderTest, DashedLineAlternatesDashesAndGaps) {
  const scene::Image image = draw(test_scene(), test_camera());
  int dash = 0, gap = 0, changes = 0;
  bool was_dash = false;
  for (int x = 70; x < 330; ++x) {
    const bool is_dash = near(pixel(image, x, 39), kPurple, 40);
    const bool is_gap = near(pixel(image, x, 39), kBackground, 2);
    dash += is_dash;
    gap += is_gap;
    changes += x > 70 && is_dash != was_dash;
    was_dash = is_dash;
  }
  EXPECT_GT(dash, 60);
  EXPECT_GT(gap, 40);
  EXPECT_GT(changes, 20) << save_for_inspection(image, "dashes");
}

TEST_P(RenderTest, CircleIsARingWithAnEmptyCentre) {
  const scene::Image image = draw(test_scene(), test_camera());
  EXPECT_LT(luminance(pixel(image, 319, 240)), 40);  // on the ring
  EXPECT_LT(luminance(pixel(image, 240, 240)), 40);  // on the ring, other side
  EXPECT_PRED3(near, pixel(image, 280, 240), kBackground, 0);  // centre: not filled
  EXPECT_PRED3(near, pixel(image, 300, 240), kBackground, 0);
  // Antialiased: between ring and background, some pixel is neither.
  int partial = 0;
  for (int x = 310; x < 330; ++x) {
    const int l = luminance(pixel(image, x, 230));
    partial += l > 40 && l < 230;
  }
  EXPECT_GE(partial, 1);
}

TEST_P(RenderTest, ImageRowsRunTopToBottom) {
  // The marker sits near the world's top: it must be in the picture's top rows.
  const scene::Image image = draw(test_scene(), test_camera());
  EXPECT_PRED3(near, pixel(image, 320, 60), kMarker, 2);
  EXPECT_PRED3(near, pixel(image, 320, kSize - 1 - 60), kBackground, 0);
}

TEST_P(RenderTest, CaptionIsWrittenAcrossTheTop) {
  scene::Scene s = test_scene();
  const scene::Image with = draw(s, test_camera());
  EXPECT_GT(dark_pixels(with, 0, 0, 250, 30), 60) << save_for_inspection(with, "caption");
  s.visible.set(Layer::caption, false);
  const scene::Image without = draw(s, test_camera());
  EXPECT_EQ(dark_pixels(without, 0, 0, 250, 30), 0);
}

TEST_P(RenderTest, FillLayerOffLeavesTheEdges) {
  scene::Scene s = test_scene();
  s.visible.set(Layer::fill, false);
  const scene::Image image = draw(s, test_camera());
  EXPECT_PRED3(near, pixel(image, 93, 306), kBackground, 0);
  EXPECT_PRED3(near, pixel(image, 146, 253), kBackground, 0);
  EXPECT_LT(luminance(pixel(image, 120, 280)), 100);
}

TEST_P(RenderTest, EachLayerSwitchesOff) {
  scene::Scene s = test_scene();
  s.visible.set(Layer::fill, false).set(Layer::edges, false).set(Layer::segments, false);
  s.visible.set(Layer::overlay, false).set(Layer::vertices, false).set(Layer::caption, false);
  const scene::Image image = draw(s, test_camera());
  for (auto [x, y] : {std::pair{120, 280}, {200, 79}, {319, 240}, {320, 60}, {93, 306}})
    EXPECT_PRED3(near, pixel(image, x, y), kBackground, 0) << "at " << x << ", " << y;
  EXPECT_EQ(dark_pixels(image, 0, 0, kSize, kSize, 245), 0) << save_for_inspection(image, "all_off");
}

TEST_P(RenderTest, MultisampledPictureKeepsTheColours) {
  const scene::Image image = draw(test_scene(), test_camera(), 4);
  EXPECT_GT(renderer_->samples(), 1);
  EXPECT_PRED3(near, pixel(image, 93, 306), kRed, 2);
  EXPECT_PRED3(near, pixel(image, 146, 253), kGreen, 2);
  EXPECT_PRED3(near, pixel(image, 200, 79), kBlue, 2);
  EXPECT_PRED3(near, pixel(image, 320, 60), kMarker, 2);
  EXPECT_PRED3(near, pixel(image, kSize - 1, kSize - 1), kBackground, 0);
}

TEST_P(RenderTest, LabelIsWrittenAtItsPoint) {
  scene::Scene s = test_scene();
  s.labels.push_back({{70, 60}, "Lepp 1", kText, 14.0f, 4.0f, 0.0f});  // pixel (280, 160) + 4 px right
  const scene::Image with = draw(s, test_camera());
  EXPECT_GT(dark_pixels(with, 284, 146, 340, 164), 20) << save_for_inspection(with, "label");
  EXPECT_EQ(dark_pixels(with, 240, 146, 282, 164), 0);  // nothing left of the anchor
  s.visible.set(Layer::labels, false);
  EXPECT_EQ(dark_pixels(draw(s, test_camera()), 284, 146, 340, 164), 0);
}

TEST_P(RenderTest, LegendShowsItsColourBar) {
  scene::Scene s = test_scene();
  scene::Legend legend;
  legend.title = "smallest angle";
  legend.colors = {{0, 0, 255, 255}, {255, 0, 0, 255}};
  legend.ticks = {{0.0, "0"}, {1.0, "60"}};
  s.legend = legend;
  const scene::Camera camera = test_camera(800, 400);  // wide enough to have room for a legend
  const auto count_blue = [](const scene::Image& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = image.width / 2; x < image.width; ++x) n += near(pixel(image, x, y), {0, 0, 255, 255}, 12);
    return n;
  };
  const scene::Image with = draw(s, camera);
  EXPECT_GT(count_blue(with), 10) << save_for_inspection(with, "legend");
  s.visible.set(Layer::legend, false);
  EXPECT_EQ(count_blue(draw(s, camera)), 0);
}

TEST_P(RenderTest, TransparentBackgroundGivesStraightAlpha) {
  scene::Scene s = test_scene();
  s.background = {0, 0, 0, 0};
  scene::Shape veil;
  veil.layer = scene::Layer::overlay;
  veil.kind = scene::ShapeKind::triangles;
  veil.color = {0, 0, 255, 128};
  veil.points = {{60, 10}, {95, 10}, {95, 30}};  // over nothing but the background
  s.shapes.push_back(veil);
  const scene::Image image = draw(s, test_camera());
  EXPECT_EQ(pixel(image, 0, kSize - 1).a, 0);
  EXPECT_PRED3(near, pixel(image, 93, 306), kRed, 2);
  // The translucent blue over nothing stays blue, half transparent (not darkened).
  EXPECT_PRED3(near, pixel(image, 360, 340), (Rgba{0, 0, 255, 128}), 3);
}

TEST_P(RenderTest, CameraMovesDoNotUploadTheMeshAgain) {
  scene::Scene s = test_scene();
  scene::Camera camera = test_camera();
  draw(s, camera);
  camera.pan(10, 5);
  camera.zoom_at({200, 200}, 1.5);
  draw(s, camera);
  EXPECT_EQ(renderer_->counters().frames, 2u);
  EXPECT_EQ(renderer_->counters().mesh_uploads, 1u);
  EXPECT_EQ(renderer_->counters().overlay_uploads, 1u);
}

TEST_P(RenderTest, ChangesInPlaceAreSeen) {
  scene::Scene s = test_scene();
  draw(s, test_camera());
  s.mesh.fill[0] = kBlue;  // the same scene object, changed
  EXPECT_PRED3(near, pixel(draw(s, test_camera()), 93, 306), kBlue, 2);
  EXPECT_EQ(renderer_->counters().mesh_uploads, 2u);

  s.shapes[0].points = {{10, 70}, {90, 70}};  // the solid line moves down 10 units (40 px)
  const scene::Image moved = draw(s, test_camera());
  EXPECT_PRED3(near, pixel(moved, 200, 119), kBlue, 2);
  EXPECT_PRED3(near, pixel(moved, 200, 79), kBackground, 0);
  EXPECT_EQ(renderer_->counters().mesh_uploads, 2u);
  EXPECT_EQ(renderer_->counters().overlay_uploads, 2u);
}

// The same picture, whatever the world's scale and position: the float coordinates are
// made relative and scaled in double precision.
TEST_P(RenderTest, HugeAndTinyAndFarWorldsDrawTheSamePicture) {
  const scene::Image reference = draw(test_scene(), test_camera());
  struct World {
    double offset, unit;
  };
  for (const World w : {World{0.0, 1e-300}, World{0.0, 1e300}, World{1e9, 1e-3}, World{-3e12, 7.0}}) {
    scene::Scene s = test_scene();
    const auto map = [&](Point& p) { p = {w.offset + p.x * w.unit, w.offset + p.y * w.unit}; };
    for (Point& p : s.mesh.points) map(p);
    for (scene::Shape& shape : s.shapes) {
      for (Point& p : shape.points) map(p);
      for (double& r : shape.radii) r *= w.unit;
    }
    map(s.bounds.lo);
    map(s.bounds.hi);
    const scene::Camera camera({w.offset + 50 * w.unit, w.offset + 50 * w.unit}, 4.0 / w.unit, kSize, kSize);
    const scene::Image image = draw(s, camera);
    const scene::ImageDiff diff = scene::compare_images(reference, image, 5);
    EXPECT_LE(diff.differing_pixels, std::size_t{kSize} * kSize / 1000)
        << "offset " << w.offset << ", unit " << w.unit << ": " << save_for_inspection(image, "world")
        << " differs from " << save_for_inspection(reference, "world_reference");
  }
}

TEST_P(RenderTest, DeepZoomKeepsEdgesInPlace) {
  // Ten million times closer, onto the middle of the shared edge (world (30, 30)): at this
  // zoom floats relative to the mesh's centre would be off by tens of pixels; the renderer
  // re-centres its coordinates instead.
  const scene::Scene s = test_scene();
  draw(s, test_camera());
  const scene::Camera camera({30.0, 30.0}, 4e7, kSize, kSize);
  const scene::Image image = draw(s, camera);
  EXPECT_EQ(renderer_->counters().mesh_uploads, 2u);  // re-centred
  // The edge runs through the centre, from top-left to bottom-right on screen; red below it.
  EXPECT_LT(luminance(pixel(image, 200, 200)), 100) << save_for_inspection(image, "deep_zoom");
  EXPECT_LT(luminance(pixel(image, 100, 100)), 100);
  EXPECT_PRED3(near, pixel(image, 150, 250), kRed, 2);
  EXPECT_PRED3(near, pixel(image, 250, 150), kGreen, 2);
}

INSTANTIATE_TEST_SUITE_P(Backends, RenderTest, ::testing::Values(Backend::egl, Backend::osmesa),
                         [](const ::testing::TestParamInfo<Backend>& info) { return backend_label(info.param); });

}  // namespace
}  // namespace meshstep::render::testing
