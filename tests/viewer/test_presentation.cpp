// Presentation mode (issue 29, item 3): the UI scale rasterises the fonts again at the
// scaled size, Tab gives the whole window to the canvas, F11 fills the screen (in a window),
// and the high-contrast theme reaches the canvas. Driven by scripts, off screen and in a
// window under xvfb-run, as test_viewer_program.cpp.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "golden_runs.hpp"
#include "meshstep/scene/image.hpp"
#include "meshstep/scene/layout.hpp"
#include "program_support.hpp"
#include "ui_look.hpp"

namespace meshstep::viewer {
namespace {

using testing::field;
using testing::has;
using testing::read_text;
using testing::Result;

// The number after "KEY": inside the object that follows "OBJECT": in the state.
double inner(const std::string& json, const std::string& object, const std::string& key) {
  const auto at = json.find("\"" + object + "\": {");
  if (at == std::string::npos) return -1;
  const std::string tag = "\"" + key + "\": ";
  const auto k = json.find(tag, at);
  return k == std::string::npos ? -1 : std::atof(json.c_str() + k + tag.size());
}

TEST(UiScale, ValidScalesAreQuarterStepsFromThreeQuartersToThree) {
  for (const char* good : {"0.75", "1", "1.25", "1.5", "2", "2.75", "3", "3.0"}) EXPECT_TRUE(parse_ui_scale(good)) << good;
  for (const char* bad : {"0.5", "3.25", "1.3", "", "1.5x", "nan", "inf", "-1", "1,5"}) EXPECT_FALSE(parse_ui_scale(bad)) << bad;
  EXPECT_EQ(*parse_ui_scale("1.5"), 1.5f);
  EXPECT_EQ(step_ui_scale(1.0f, +1), 1.25f);
  EXPECT_EQ(step_ui_scale(1.0f, -1), 0.75f);
  EXPECT_EQ(step_ui_scale(0.75f, -1), 0.75f) << "held at the smallest";
  EXPECT_EQ(step_ui_scale(3.0f, +1), 3.0f) << "held at the largest";
  EXPECT_EQ(format_ui_scale(1.5f), "1.5");
  EXPECT_EQ(format_ui_scale(1.0f), "1");
  for (const scene::Theme t : {scene::Theme::light, scene::Theme::dark, scene::Theme::high_contrast})
    EXPECT_EQ(parse_theme(theme_name(t)), t);
  EXPECT_FALSE(parse_theme("contrast"));
}

TEST(CanvasTextScale, TheCaptionAndLegendGrowAndTheFitLeavesThemRoom) {
  scene::Scene s;
  s.caption = "refine \u00B7 step 30 of 50";
  s.legend = scene::Legend{};
  s.legend->title = "smallest angle";
  const scene::Layout one = scene::layout(s, 1280, 720);
  s.text_scale = 2.0f;
  const scene::Layout two = scene::layout(s, 1280, 720);
  ASSERT_TRUE(one.caption_band && two.caption_band && one.legend && two.legend);
  EXPECT_DOUBLE_EQ(two.caption.size_px, 2 * one.caption.size_px);
  EXPECT_DOUBLE_EQ(two.caption_band->h, 2 * one.caption_band->h);
  EXPECT_DOUBLE_EQ(two.legend->title.size_px, 2 * one.legend->title.size_px);
  EXPECT_DOUBLE_EQ(two.margins.top, 2 * one.margins.top);
  EXPECT_DOUBLE_EQ(two.margins.right, 2 * one.margins.right);
  EXPECT_GT(two.legend->panel.w, one.legend->panel.w);
}

class Presentation : public testing::ScriptedViewer {
 protected:
  Presentation() : ScriptedViewer("viewer_presentation", "1024x640") {}
  void SetUp() override {
    ScriptedViewer::SetUp();
    log_ = golden::lesson_run("--algorithm offcenter --min-angle 30");
    ASSERT_NE(log_, nullptr);
  }
};

TEST_P(Presentation, TheUiScaleRasterisesTheFontsAgainAtTheScaledSize) {
  const std::string a = path("a.json"), b = path("b.json"), c = path("c.json"), d = path("d.json");
  VIEW_OR_SKIP(r, "seek step 20\nframes 2\nstate " + a + "\nkey Ctrl+=\nkey Ctrl+=\nstate " + b +
                      "\nui-scale 3\nkey Ctrl+=\nstate " + c + "\nkey Ctrl+-\nui-scale 0.75\nkey Ctrl+-\nstate " + d +
                      "\nquit\n");
  const std::string sa = read_text(a), sb = read_text(b), sc = read_text(c), sd = read_text(d);
  EXPECT_TRUE(has(sa, "\"ui_scale\": 1,")) << sa;
  EXPECT_EQ(field(sa, "font_pixels"), 16);
  EXPECT_TRUE(has(sb, "\"ui_scale\": 1.5,")) << sb;
  EXPECT_EQ(field(sb, "font_pixels"), 24) << "two steps of 0.25: 16 px x 1.5";
  EXPECT_TRUE(has(sc, "\"ui_scale\": 3,")) << "Ctrl+= at 3 stays at 3: " << sc;
  EXPECT_EQ(field(sc, "font_pixels"), 48);
  EXPECT_TRUE(has(sd, "\"ui_scale\": 0.75,")) << "Ctrl+- at 0.75 stays at 0.75: " << sd;
  EXPECT_EQ(field(sd, "font_pixels"), 12);
  // Rasterised, not stretched: the atlas the texture is made from grows with the letters.
  const double ha = inner(sa, "font_atlas", "height"), hb = inner(sb, "font_atlas", "height");
  const double hc = inner(sc, "font_atlas", "height"), hd = inner(sd, "font_atlas", "height");
  EXPECT_GT(hb, ha);
  EXPECT_GT(hc, hb);
  EXPECT_LT(hd, ha);
  // The panels grow with the text: the side panel is 380 px at scale 1, 570 at 1.5 but
  // never more than 40% of the window (409.6 px of 1024), which the canvas keeps.
  EXPECT_EQ(inner(sa, "canvas_rect", "width"), 1024 - 380);
  EXPECT_FLOAT_EQ(inner(sb, "canvas_rect", "width"), 1024 - 0.4f * 1024);
}

// The canvas's caption band: its ink grows with the UI scale (the words are drawn larger,
// not only the panels).
std::size_t dark_pixels_in_rows(const scene::Image& image, int rows) {
  std::size_t n = 0;
  for (int y = 0; y < rows && y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
      if (image.rgba[i] < 100 && image.rgba[i + 1] < 100 && image.rgba[i + 2] < 100) ++n;
    }
  return n;
}

TEST_P(Presentation, TheCanvasWordsGrowWithTheUiScale) {
  const std::string one = path("one.png"), two = path("two.png");
  VIEW_OR_SKIP(r, "seek step 30\nframes 2\ncanvas " + one + "\nui-scale 2\nframes 2\ncanvas " + two + "\nquit\n");
  const scene::Image a = scene::read_png(one), b = scene::read_png(two);
  // The caption band is 30 px high at scale 1 and 60 at 2: the same words, larger, leave
  // more ink. Not four times: step 30's caption is wider than the canvas beside the panel at
  // scale 2, and a caption that would run under the panel is set smaller to fit (down to 60%
  // of its scaled size; scene/layout.cpp), here about 1.8 times the ink.
  EXPECT_GT(2 * dark_pixels_in_rows(b, 60), 3 * dark_pixels_in_rows(a, 30))
      << dark_pixels_in_rows(b, 60) << " vs " << dark_pixels_in_rows(a, 30);
}

TEST_P(Presentation, TabHidesThePanelsAndTheCanvasFillsTheWindow) {
  const std::string a = path("a.json"), b = path("b.json"), c = path("c.json"), d = path("d.json");
  VIEW_OR_SKIP(r, "seek step 20\nframes 2\nstate " + a + "\nkey Tab\nstate " + b + "\nkey Tab\nstate " + c +
                      "\npanels hide\nstate " + d + "\nquit\n");
  const std::string sa = read_text(a), sb = read_text(b), sc = read_text(c), sd = read_text(d);
  EXPECT_EQ(inner(sa, "window", "width"), 1024);
  EXPECT_EQ(inner(sa, "window", "height"), 640);
  EXPECT_LT(inner(sa, "canvas_rect", "width"), 1024) << sa;
  EXPECT_LT(inner(sa, "canvas_rect", "height"), 640) << "the timeline is under the canvas: " << sa;
  EXPECT_TRUE(has(sa, "\"panels_hidden\": false")) << sa;
  for (const std::string* s : {&sb, &sd}) {
    EXPECT_TRUE(has(*s, "\"panels_hidden\": true")) << *s;
    EXPECT_EQ(inner(*s, "canvas_rect", "x"), 0);
    EXPECT_EQ(inner(*s, "canvas_rect", "y"), 0);
    EXPECT_EQ(inner(*s, "canvas_rect", "width"), 1024) << *s;
    EXPECT_EQ(inner(*s, "canvas_rect", "height"), 640) << *s;
  }
  EXPECT_EQ(inner(sc, "canvas_rect", "width"), inner(sa, "canvas_rect", "width")) << "Tab again brings them back";
  // The run is fitted again to the larger canvas (the camera was not moved by hand).
  EXPECT_GT(inner(sb, "camera", "pixels_per_unit"), 1.2 * inner(sa, "camera", "pixels_per_unit")) << sb;
}

// The canvas's pixels that are nearly black: mesh lines and segments (and text).
std::size_t dark_pixels(const scene::Image& image) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
    if (image.rgba[i] < 40 && image.rgba[i + 1] < 40 && image.rgba[i + 2] < 40) ++n;
  return n;
}

TEST_P(Presentation, TheHighContrastThemeDrawsBlackLinesOnWhite) {
  const std::string a = path("a.json"), b = path("b.json"), c = path("c.json");
  const std::string light = path("light.png"), contrast = path("contrast.png");
  VIEW_OR_SKIP(r, "seek step 40\ncolor-by none\nframes 2\ncanvas " + light + "\nstate " + a + "\nkey Shift+T\nstate " +
                      b + "\ncanvas " + contrast + "\nkey Shift+T\ntheme high-contrast\nstate " + c + "\nquit\n");
  EXPECT_TRUE(has(read_text(a), "\"theme\": \"light\"")) << read_text(a);
  EXPECT_TRUE(has(read_text(b), "\"theme\": \"high-contrast\"")) << read_text(b);
  EXPECT_TRUE(has(read_text(c), "\"theme\": \"high-contrast\"")) << read_text(c);
  const scene::Image l = scene::read_png(light), h = scene::read_png(contrast);
  ASSERT_EQ(l.rgba.size(), h.rgba.size());
  // White paper in both; the light theme's edges are translucent grey, the high-contrast
  // theme's opaque black and twice as wide.
  EXPECT_EQ(h.rgba[0], 255);
  EXPECT_EQ(h.rgba[1], 255);
  EXPECT_EQ(h.rgba[2], 255);
  EXPECT_GT(dark_pixels(h), 2 * dark_pixels(l)) << dark_pixels(h) << " vs " << dark_pixels(l);
}

TEST_P(Presentation, F11FillsTheScreenInAWindowAndSaysWhyNotOffScreen) {
  const std::string a = path("a.json"), b = path("b.json"), c = path("c.json");
  VIEW_OR_SKIP(r, "seek step 20\nframes 2\nkey F11\nframes 4\nstate " + a + "\nkey F11\nframes 4\nstate " + b +
                      "\nfull-screen on\nframes 4\nstate " + c + "\nquit\n");
  const std::string sa = read_text(a), sb = read_text(b), sc = read_text(c);
  if (GetParam() == "window") {
    // xvfb-run's screen is 1280x800 (program_support.hpp): the window fills it, and comes
    // back to its own size.
    EXPECT_TRUE(has(sa, "\"full_screen\": true")) << sa;
    EXPECT_EQ(inner(sa, "window", "width"), 1280) << sa;
    EXPECT_EQ(inner(sa, "window", "height"), 800) << sa;
    EXPECT_TRUE(has(sb, "\"full_screen\": false")) << sb;
    EXPECT_EQ(inner(sb, "window", "width"), 1024) << sb;
    EXPECT_EQ(inner(sb, "window", "height"), 640) << sb;
    EXPECT_TRUE(has(sc, "\"full_screen\": true")) << sc;
  } else {
    for (const std::string* s : {&sa, &sc}) {
      EXPECT_TRUE(has(*s, "\"full_screen\": false")) << *s;
      EXPECT_TRUE(has(*s, "off screen there is no window")) << *s;
      EXPECT_EQ(inner(*s, "window", "width"), 1024);
    }
  }
}

TEST_P(Presentation, TheUiScaleOptionIsCheckedAndReachesTheViewer) {
  const std::string a = path("a.json");
  VIEW_OR_SKIP(r, "frames 2\nstate " + a + "\nquit\n", "--ui-scale 1.5");
  EXPECT_TRUE(has(read_text(a), "\"ui_scale\": 1.5,")) << read_text(a);
  EXPECT_EQ(field(read_text(a), "font_pixels"), 24);
  for (const char* bad : {"1.3", "4", "big"}) {
    const Result refused = view("quit\n", std::string("--ui-scale ") + bad);
    if (refused.status == 77) continue;
    EXPECT_EQ(refused.status, 2) << bad << ": " << refused.output;
    EXPECT_TRUE(has(refused.output, std::string("--ui-scale ") + bad + ": expected 0.75 to 3")) << refused.output;
  }
}

// A person's viewer (no script) keeps --ui-scale in its settings file when it closes (here
// by SIGTERM, as Ctrl+C in the terminal), and starts from it the next time.
TEST(PresentationSettings, TheUiScaleIsKeptInTheSettingsFile) {
  if (testing::run("command -v xvfb-run").status != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const replay::LogReader* log = golden::lesson_run("--algorithm offcenter --min-angle 30");
  ASSERT_NE(log, nullptr);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("viewer_presentation_settings_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string ini = (dir / "viewer.ini").string();
  const auto close_after_a_while = [&](const std::string& extra) {
    return testing::run("MESHSTEP_VIEWER_CONFIG='" + ini + "' xvfb-run -a -s '-screen 0 1280x800x24' sh -c '" +
                        MESHSTEP_VIEW_BINARY + " " + log->path() + " --size 800x600 -q " + extra +
                        " & pid=$!; sleep 2; kill -TERM $pid; wait $pid'");
  };
  const Result first = close_after_a_while("--ui-scale 1.75");
  if (testing::has(first.output, "cannot open a window")) GTEST_SKIP() << first.output;
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_TRUE(has(read_text(ini), "\nui_scale = 1.75\n")) << read_text(ini);
  // Without the option, the file's scale is the one used and kept.
  const Result second = close_after_a_while("");
  ASSERT_EQ(second.status, 0) << second.output;
  EXPECT_TRUE(has(read_text(ini), "\nui_scale = 1.75\n")) << read_text(ini);
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

INSTANTIATE_TEST_SUITE_P(Modes, Presentation, ::testing::Values("egl", "osmesa", "window"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace meshstep::viewer
