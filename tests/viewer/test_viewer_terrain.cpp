// The viewer program on a terrain's run, driven by scripts: off screen on EGL and on
// OSMesa, and in a real window under xvfb-run. The 3D view switched on by its key and by its
// script command, turned by keys, by a drag and by `orbit`, its state read back exactly and
// its window checked for what only a 3D picture has (the surface coloured by height, with
// the height legend); stepping in 3D, the inspector's click on the picture, the canvas's
// worker drawing the same, idle frames allocating nothing; and a planar run refusing it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "golden_runs.hpp"
#include "inspector.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/image.hpp"
#include "program_support.hpp"
#include "view_3d.hpp"

namespace meshstep::viewer {
namespace {

using testing::field;
using testing::frame_allocations;
using testing::has;
using testing::read_text;
using testing::Result;
using testing::run;

namespace fs = std::filesystem;

constexpr const char* kLeppSurface = "--max-error 1";
// The window the scripts draw, and its canvas (the side panel is 380 pixels wide and the
// timeline 122 high unless settings say otherwise; scripts read no settings).
constexpr int kWidth = 1024, kHeight = 640, kCanvasWidth = kWidth - 380, kCanvasHeight = kHeight - 122;

// A number after "KEY": anywhere in the state (the orbit's and the camera's fields share a line).
double number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  return at == std::string::npos ? NAN : std::atof(json.c_str() + at + key.size() + 4);
}

// A string field's text, or "" when absent or null.
std::string text(const std::string& json, const std::string& key) {
  const std::string tag = "\"" + key + "\": \"";
  const auto at = json.find(tag);
  if (at == std::string::npos) return "";
  return json.substr(at + tag.size(), json.find("\",\n", at) - at - tag.size());
}

// The pixels of the canvas (the window's top left, above the timeline) within `tolerance`
// of `colour` in every channel.
std::size_t canvas_pixels_near(const scene::Image& window, scene::Rgba colour, int tolerance) {
  std::size_t n = 0;
  for (int y = 0; y < std::min(kCanvasHeight, window.height); ++y)
    for (int x = 0; x < std::min(kCanvasWidth, window.width); ++x) {
      const std::uint8_t* p = window.row(y) + static_cast<std::size_t>(x) * 4;
      n += std::abs(p[0] - colour.r) <= tolerance && std::abs(p[1] - colour.g) <= tolerance &&
           std::abs(p[2] - colour.b) <= tolerance;
    }
  return n;
}

// The ends of the height colour map (viridis), as the legend's bar shows them unshaded.
constexpr scene::Rgba kLowest{68, 1, 84, 255}, kHighest{253, 231, 37, 255};

class ViewerTerrain : public testing::ScriptedViewer {
 protected:
  ViewerTerrain() : ScriptedViewer("viewer_terrain", std::to_string(kWidth) + "x" + std::to_string(kHeight)) {}
  void SetUp() override {
    ScriptedViewer::SetUp();
    log_ = golden::terrain_run(kLeppSurface);
    ASSERT_NE(log_, nullptr);
  }
};

// V switches to 3D; the keys, the script's `orbit` and `z-scale`, and a drag on the canvas
// turn it; the window shows a surface coloured by height, which the 2D window does not.
TEST_P(ViewerTerrain, SwitchesTo3dTurnsAndShowsTheSurface) {
  VIEW_OR_SKIP(r, "seek step 30\nframes 2\nstate " + path("flat.json") + "\nscreenshot " + path("flat.png") +
                      "\nkey V\nframes 1\nstate " + path("3d.json") + "\nscreenshot " + path("3d.png") +
                      "\norbit -30 50\nz-scale 2\nkey Ctrl+Right\nkey Ctrl+Up\nframes 1\nstate " + path("keys.json") +
                      "\nmouse 300 250\ndrag 100 -20\nframes 1\nstate " + path("dragged.json") +
                      "\nkey V\nframes 1\nstate " + path("back.json") + "\nquit\n");
  const std::string flat = read_text(path("flat.json")), in_3d = read_text(path("3d.json")),
                    keys = read_text(path("keys.json")), dragged = read_text(path("dragged.json")),
                    back = read_text(path("back.json"));
  EXPECT_TRUE(has(flat, "\"view\": \"2d\"")) << flat;
  EXPECT_TRUE(has(flat, "\"view_3d_available\": true")) << flat;
  EXPECT_TRUE(has(in_3d, "\"view\": \"3d\"")) << in_3d;
  EXPECT_TRUE(has(in_3d, "\"orbit\": {\"azimuth\": -60, \"elevation\": 35, \"z_scale\": 1}")) << in_3d;
  EXPECT_TRUE(has(in_3d, "\"caption\": \"refine \u00B7 step 30 of ")) << in_3d;
  EXPECT_TRUE(has(text(in_3d, "caption"), "\u00B7 3D -60\u00B0, 35\u00B0")) << in_3d;
  // orbit -30 50, the heights doubled, then 15 degrees of azimuth and 5 of elevation more.
  EXPECT_EQ(number(keys, "azimuth"), -15.0) << keys;
  EXPECT_EQ(number(keys, "elevation"), 55.0) << keys;
  EXPECT_EQ(number(keys, "z_scale"), 2.0) << keys;
  EXPECT_TRUE(has(text(keys, "caption"), "3D -15\u00B0, 55\u00B0, heights \u00D72")) << keys;
  // A drag of 100 pixels right and 20 up: half a degree a pixel, the near side following.
  EXPECT_EQ(number(dragged, "azimuth"), -65.0) << dragged;
  EXPECT_EQ(number(dragged, "elevation"), 45.0) << dragged;
  EXPECT_TRUE(has(dragged, "\"view\": \"3d\"")) << dragged;
  // Back to 2D: the 2D camera as it was, the orbit kept for the next time.
  EXPECT_TRUE(has(back, "\"view\": \"2d\"")) << back;
  EXPECT_EQ(number(back, "x"), number(flat, "x")) << back;
  EXPECT_EQ(number(back, "pixels_per_unit"), number(flat, "pixels_per_unit")) << back;
  EXPECT_EQ(number(back, "azimuth"), -65.0) << back;
  EXPECT_EQ(text(back, "caption"), text(flat, "caption"));

  // The 3D window: the surface in the height map's colours, the legend's bar from its lowest
  // to its highest; the 2D one (coloured by nothing) has neither, and the two differ on a
  // good part of the canvas.
  const scene::Image flat_png = scene::read_png(path("flat.png")), png = scene::read_png(path("3d.png"));
  ASSERT_EQ(png.width, kWidth);
  ASSERT_EQ(png.height, kHeight);
  EXPECT_GT(canvas_pixels_near(png, kLowest, 12), 20u);
  EXPECT_GT(canvas_pixels_near(png, kHighest, 12), 20u);
  EXPECT_EQ(canvas_pixels_near(flat_png, kLowest, 12), 0u);
  EXPECT_EQ(canvas_pixels_near(flat_png, kHighest, 12), 0u);
  const scene::ImageDiff diff = scene::compare_images(flat_png, png, 5);
  EXPECT_GT(diff.differing_pixels, static_cast<std::size_t>(kCanvasWidth) * kCanvasHeight / 5);
}

// Stepping in 3D: the caption says the worst triangle's error and where the sample went, the
// explanation and the pseudo-code are those of 2D, and the timeline moves the moment.
TEST_P(ViewerTerrain, SteppingIn3dSaysTheErrorAndTheSample) {
  VIEW_OR_SKIP(r, "seek step 20\nframes 1\nstate " + path("2d.json") + "\nview 3d\nframes 1\nstate " +
                      path("3d.json") + "\nkey Right\nframes 1\nstate " + path("next.json") + "\nquit\n");
  const std::string flat = read_text(path("2d.json")), in_3d = read_text(path("3d.json")),
                    next = read_text(path("next.json"));
  EXPECT_TRUE(has(text(in_3d, "caption"), "vertical error")) << in_3d;
  EXPECT_TRUE(has(text(in_3d, "caption"), "inserted")) << in_3d;
  // The words do not depend on the view.
  for (const char* key : {"explain_heading", "code_title", "code_line"}) EXPECT_EQ(text(in_3d, key), text(flat, key)) << key;
  const auto explain = [](const std::string& json) { return json.substr(json.find("\"explain\": ["), 600); };
  EXPECT_EQ(explain(in_3d), explain(flat));
  EXPECT_TRUE(has(in_3d, "next sample: ")) << in_3d;
  EXPECT_EQ(text(in_3d, "code_title").rfind("Lepp-surface terrain approximation", 0), 0u) << in_3d;
  // The camera holds still while stepping (it fits the whole run's box, not the moment's).
  EXPECT_EQ(field(next, "step"), 21);
  EXPECT_TRUE(has(next, "\"view\": \"3d\"")) << next;
  EXPECT_TRUE(has(text(next, "caption"), "step 21 of ")) << next;
  EXPECT_EQ(number(next, "x"), number(in_3d, "x"));
  EXPECT_EQ(number(next, "pixels_per_unit"), number(in_3d, "pixels_per_unit"));
}

// A click on the 3D picture selects the front triangle under the pointer: the one the
// inspector's pick finds on the lifted scene of that moment, as the camera in the state
// puts it on the canvas.
TEST_P(ViewerTerrain, AClickOnThe3dPictureSelectsTheTriangleShownThere) {
  constexpr int kX = 330, kY = 260;
  VIEW_OR_SKIP(r, "seek step 60\nview 3d\norbit -40 30\nframes 2\nmouse " + std::to_string(kX) + " " +
                      std::to_string(kY) + "\nclick\nframes 1\nstate " + path("picked.json") + "\nquit\n");
  const std::string picked = read_text(path("picked.json"));
  const scene::Camera camera({number(picked, "x"), number(picked, "y")}, number(picked, "pixels_per_unit"), kCanvasWidth,
                             kCanvasHeight);
  replay::Replay cursor(*log_);
  cursor.seek_step(60);
  const scene::Scene planar = scene::build_scene(cursor, {});
  View3d view(log_);
  view.set_orbit({-40.0, 30.0, 1.0});
  const scene::Scene& lifted = view.lifted(planar, 1, SIZE_MAX);
  const Picked front = pick_front(lifted.mesh, camera.to_world({kX, kY}), 8.0 / camera.pixels_per_unit());
  ASSERT_NE(front.kind, Picked::Kind::none) << "the pointer is over the surface";
  if (front.kind == Picked::Kind::vertex) {  // within 8 pixels of a vertex: the vertex
    EXPECT_TRUE(has(picked, "\"selection\": \"vertex " + log_->vertex_name(front.index) + " at")) << picked;
    EXPECT_TRUE(has(picked, ", height ")) << picked;
    return;
  }
  const std::uint32_t t = find_triangle(planar.mesh, lifted.mesh.triangles[front.index]);
  ASSERT_NE(t, kNoIndex);
  const auto& v = planar.mesh.triangles[t];
  const std::string expected = "\"selection\": \"triangle " + log_->vertex_name(v[0]) + " " + log_->vertex_name(v[1]) +
                               " " + log_->vertex_name(v[2]) + ": ";
  EXPECT_TRUE(has(picked, expected)) << expected << "\n" << picked;
  // A terrain's Lepp path is measured in 3D, as Lepp-surface measures it.
  const LeppPath lepp = lepp_path(planar.mesh, t, view.heights());
  const std::string path_words = "Lepp path of " + std::to_string(lepp.triangles.size()) + " to edge " +
                                 log_->vertex_name(lepp.a) + "-" + log_->vertex_name(lepp.b);
  EXPECT_TRUE(has(picked, path_words)) << path_words << "\n" << picked;
}

// The canvas's worker draws the same 3D window as this thread; and in 3D, on either, the
// idle frames allocate nothing while the frame of a turn does.
TEST_P(ViewerTerrain, TheWorkerDrawsTheSame3dWindowAndIdleFramesDoNotAllocate) {
  const auto script = [&](const std::string& name) {
    return "seek step 45\nview 3d\nz-scale 2\nwait\nframes 6\nkey Ctrl+Right\nsettle\nframes 20\nstate " +
           path(name + ".json") +
           "\nscreenshot " + path(name + ".png") + "\nquit\n";
  };
  VIEW_OR_SKIP(m, script("main"), "--canvas main --frame-log " + path("main.txt"));
  VIEW_OR_SKIP(w, script("worker"), "--canvas worker --frame-log " + path("worker.txt"));
  const std::string main = read_text(path("main.json")), worker = read_text(path("worker.json"));
  EXPECT_TRUE(has(worker, "\"canvas\": \"worker\"")) << worker;
  for (const char* key : {"caption", "explain_heading", "code_line"}) EXPECT_EQ(text(worker, key), text(main, key)) << key;
  for (const char* key : {"x", "y", "pixels_per_unit", "azimuth", "elevation", "z_scale"})
    EXPECT_EQ(number(worker, key), number(main, key)) << key;
  const scene::Image a = scene::read_png(path("main.png")), b = scene::read_png(path("worker.png"));
  const scene::ImageDiff diff = scene::compare_images(a, b, 5);
  EXPECT_TRUE(diff.same_size);
  EXPECT_LE(diff.differing_pixels, static_cast<std::size_t>(a.width) * a.height / 1000);

  const auto allocations = [](const std::string& file) { return frame_allocations(file); };
  // This thread: frames 0 and 1 warm up, 2-5 idle, 6 turns (a new lift and picture), then idle.
  const std::vector<unsigned long long> on_main = allocations(path("main.txt"));
  ASSERT_GE(on_main.size(), 27u);
  for (std::size_t i = 2; i < 6; ++i) EXPECT_EQ(on_main[i], 0u) << "idle frame " << i;
  if (MESHSTEP_VIEW_COUNTS_NEW) {
    EXPECT_GT(on_main[6], 0u) << "the frame of the turn";
  }
  for (std::size_t i = 8; i < 27; ++i) EXPECT_EQ(on_main[i], 0u) << "idle frame " << i;
  // The worker: once its picture of the turn is in (the script settles the canvas), idle.
  const std::vector<unsigned long long> on_worker = allocations(path("worker.txt"));
  ASSERT_GE(on_worker.size(), 27u);
  for (std::size_t i = 12; i < 27; ++i) EXPECT_EQ(on_worker[i], 0u) << "idle frame " << i;
}

// The lifted picture follows every new moment and option: a seek and a new theme after a
// few frames of another moment show the new one (its caption, its dark background).
TEST_P(ViewerTerrain, The3dPictureFollowsTheMomentAndTheTheme) {
  VIEW_OR_SKIP(r, "view 3d\nseek step 40\nframes 2\nseek end\nkey T\nframes 2\nstate " + path("end.json") +
                      "\nscreenshot " + path("end.png") + "\nquit\n");
  const std::string end = read_text(path("end.json"));
  const std::string steps = std::to_string(log_->step_count());
  EXPECT_TRUE(has(text(end, "caption"), "step " + steps + " of " + steps + " ")) << end;
  EXPECT_TRUE(has(end, "\"theme\": \"dark\"")) << end;
  // The canvas's corner, away from the surface and the caption: the dark theme's background.
  const scene::Image png = scene::read_png(path("end.png"));
  const std::uint8_t* corner = png.row(kCanvasHeight - 8) + 8 * 4;
  EXPECT_LT(corner[0] + corner[1] + corner[2], 3 * 80) << "not dark: " << int(corner[0]) << " " << int(corner[1]);
}

INSTANTIATE_TEST_SUITE_P(Modes, ViewerTerrain, ::testing::Values("egl", "osmesa", "window"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// A run without heights has no 3D view: V leaves it in 2D and the canvas says why; the
// script's `view 3d` stops the script with the reason.
TEST(ViewerTerrainRefusal, APlanarRunStaysIn2dAndSaysWhy) {
  const replay::LogReader* log = golden::lesson_run("--algorithm offcenter --min-angle 30");
  ASSERT_NE(log, nullptr);
  const fs::path dir = fs::temp_directory_path() / ("viewer_planar_3d_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path script = dir / "s.txt", state = dir / "s.json";
  std::ofstream(script) << "seek step 20\nframes 1\nkey V\nframes 1\nstate " << state.string() << "\nquit\n";
  Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen -q --script " + script.string());
  if (r.status != 0 && has(r.output, "cannot open a window or draw")) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string s = read_text(state);
  EXPECT_TRUE(has(s, "\"view\": \"2d\"")) << s;
  EXPECT_TRUE(has(s, "\"view_3d_available\": false")) << s;
  EXPECT_TRUE(has(text(s, "notice"), "this run has no heights")) << s;
  EXPECT_FALSE(has(text(s, "caption"), "3D")) << s;

  std::ofstream(script) << "seek step 20\nview 3d\nquit\n";
  r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen -q --script " + script.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(has(r.output, script.string() + ":2: view 3d: ")) << r.output;
  EXPECT_TRUE(has(r.output, "has no heights")) << r.output;
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace meshstep::viewer
