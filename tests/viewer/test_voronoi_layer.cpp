// The Voronoi layer in the viewer (issue 29, item 6): off at first, Shift+V switches it on
// (the state lists it), and the canvas then shows the diagram: the layer's vermillion
// lines, which the picture before did not have; Shift+V again takes them away. Driven by a
// script, off screen and in a window under xvfb-run, as test_presentation.cpp.
#include <gtest/gtest.h>

#include <string>

#include "golden_runs.hpp"
#include "meshstep/scene/image.hpp"
#include "program_support.hpp"

namespace meshstep::viewer {
namespace {

using testing::has;
using testing::read_text;
using testing::Result;

// Pixels of the light theme's Voronoi colour (Okabe-Ito vermillion, 213 94 0), give or take
// the antialiasing.
std::size_t vermillion_pixels(const scene::Image& image) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
    n += std::abs(image.rgba[i] - 213) < 30 && std::abs(image.rgba[i + 1] - 94) < 30 && image.rgba[i + 2] < 40;
  return n;
}

class VoronoiLayer : public testing::ScriptedViewer {
 protected:
  VoronoiLayer() : ScriptedViewer("viewer_voronoi", "1024x640") {}
  void SetUp() override {
    ScriptedViewer::SetUp();
    log_ = golden::lesson_run("--algorithm offcenter --min-angle 30");
    ASSERT_NE(log_, nullptr);
  }
};

TEST_P(VoronoiLayer, ShiftVShowsTheDiagramAndHidesItAgain) {
  const std::string a = path("a.png"), b = path("b.png"), c = path("c.png");
  const std::string sa = path("a.json"), sb = path("b.json");
  // The first moment after the triangulation's carving: no overlay in vermillion to confuse.
  VIEW_OR_SKIP(r, "seek step 25\nframes 2\ncanvas " + a + "\nstate " + sa + "\nkey Shift+V\nframes 2\ncanvas " + b +
                      "\nstate " + sb + "\nkey Shift+V\nframes 2\ncanvas " + c + "\nquit\n");
  const std::string before = read_text(sa), after = read_text(sb);
  EXPECT_FALSE(has(before, "\"voronoi\"")) << before;
  EXPECT_TRUE(has(after, "\"voronoi\"")) << after;
  const std::size_t off = vermillion_pixels(scene::read_png(a)), on = vermillion_pixels(scene::read_png(b)),
                    again = vermillion_pixels(scene::read_png(c));
  EXPECT_GT(on, off + 1000) << "the diagram's lines: " << on << " vermillion pixels against " << off;
  EXPECT_EQ(again, off) << "switched off again, the picture is the first one";
}

INSTANTIATE_TEST_SUITE_P(Modes, VoronoiLayer, ::testing::Values("egl", "osmesa", "window"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace meshstep::viewer
