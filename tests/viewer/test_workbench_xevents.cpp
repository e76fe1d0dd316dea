// The workbench through real X events (issue 27: "test the same features through real mouse
// and key events under Xvfb"): an Xvfb server of the test's own, the viewer in a window on
// it, and xdotool's pointer and keys (XTEST: what a person's mouse and keyboard send). The
// viewer's script waits (`wait-until FILE`) while they arrive, touching neither mouse nor
// keys, then writes its state; the test reads it, and the camera in it says where the next
// world point is on the screen. Skipped when xdotool or Xvfb is not installed.
//
// Labelled as the other window tests (".../window"): the sanitizer pass leaves them out.
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "meshstep/io/shortest_text.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/region.hpp"
#include "meshstep/scene/image.hpp"
#include "program_support.hpp"

namespace meshstep::viewer {
namespace {

using testing::field;
using testing::has;
using testing::read_text;
using testing::Result;
using testing::run;

namespace fs = std::filesystem;

// The number after "KEY": inside the object that follows "OBJECT": (9 significant digits).
double number_in(const std::string& json, const std::string& object, const std::string& key) {
  const auto at = json.find("\"" + object + "\": {");
  if (at == std::string::npos) return NAN;
  const auto k = json.find("\"" + key + "\": ", at);
  return k == std::string::npos ? NAN : std::atof(json.c_str() + k + key.size() + 4);
}

std::string counts(const std::string& json) {
  const auto n = [&](const char* key) { return std::to_string(static_cast<long long>(number_in(json, "input", key))); };
  return n("vertices") + " " + n("segments") + " " + n("holes") + " " + n("regions");
}

// Where world points are in the window, and the reverse: the canvas's rectangle and its
// camera, as a state file gives them.
struct View {
  double left = 0, top = 0, width = 0, height = 0, cx = 0, cy = 0, scale = 1;
  explicit View(const std::string& json)
      : left(number_in(json, "canvas_rect", "x")), top(number_in(json, "canvas_rect", "y")),
        width(number_in(json, "canvas_rect", "width")), height(number_in(json, "canvas_rect", "height")),
        cx(number_in(json, "camera", "x")), cy(number_in(json, "camera", "y")),
        scale(number_in(json, "camera", "pixels_per_unit")) {}
  // The window's pixel nearest to the world point.
  std::pair<int, int> pixel(double x, double y) const {
    return {static_cast<int>(std::lround(left + 0.5 * width + (x - cx) * scale)),
            static_cast<int>(std::lround(top + 0.5 * height - (y - cy) * scale))};
  }
  Point world(int px, int py) const {
    return {cx + (px - left - 0.5 * width) / scale, cy - (py - top - 0.5 * height) / scale};
  }
};

// An Xvfb server of this test's own (its display chosen by Xvfb: -displayfd), the viewer
// in a window on it with a script, and xdotool sending to that window.
class WorkbenchXEvents : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    if (run("command -v xdotool").status != 0) GTEST_SKIP() << "xdotool is not installed (Debian package xdotool)";
    if (run("command -v Xvfb").status != 0) GTEST_SKIP() << "Xvfb is not installed (Debian package xvfb)";
    dir_ = fs::temp_directory_path() / ("viewer_xevents_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const Result x = run("Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>" + path("display") +
                         " >/dev/null 2>" + path("xvfb.log") + " & echo $! >" + path("xvfb.pid"));
    ASSERT_EQ(x.status, 0) << x.output;
    xvfb_ = std::atoi(read_text(path("xvfb.pid")).c_str());
    for (int i = 0; i < 200 && display_.empty(); ++i) {
      std::string d = read_text(path("display"));
      if (!d.empty() && d.back() == '\n') display_ = ":" + d.substr(0, d.size() - 1);
      else std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ASSERT_FALSE(display_.empty()) << "Xvfb gave no display: " << read_text(path("xvfb.log"));
  }
  void TearDown() override {
    if (viewer_ > 0 && !fs::exists(path("view.status"))) ::kill(viewer_, SIGTERM);
    if (xvfb_ > 0) ::kill(xvfb_, SIGTERM);
    std::error_code ec;
    if (!HasFailure()) fs::remove_all(dir_, ec);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Starts the viewer on FILE with the script, in the background, and waits for its window.
  void start(const std::string& file, const std::string& script) {
    std::ofstream(path("script.txt")) << script;
    const Result r = run("(DISPLAY=" + display_ + " " + MESHSTEP_VIEW_BINARY + " " + file +
                         " --window 1024x640 -q --script " + path("script.txt") + " >" + path("view.out") +
                         " 2>&1; echo $? >" + path("view.status") + ") >/dev/null 2>&1 & echo $! >" + path("view.pid"));
    ASSERT_EQ(r.status, 0) << r.output;
    viewer_ = std::atoi(read_text(path("view.pid")).c_str());
    const Result w = xdo("search --sync --onlyvisible --name 'meshstep view'", "timeout 60 ");
    ASSERT_EQ(w.status, 0) << w.output << read_text(path("view.out"));
    window_ = w.output.substr(0, w.output.find('\n'));
    xdo("windowfocus " + window_);
  }

  Result xdo(const std::string& args, const std::string& prefix = "") {
    return run(prefix + "env DISPLAY=" + display_ + " xdotool " + args);
  }
  // The pointer to pixel (x, y) of the window, then a pause: the viewer draws frames
  // meanwhile, so that each event is seen on a frame of its own.
  void move(std::pair<int, int> p) {
    ASSERT_EQ(xdo("mousemove --window " + window_ + " " + std::to_string(p.first) + " " + std::to_string(p.second) +
                  " sleep " + kPause).status, 0);
  }
  void click(std::pair<int, int> p, int button = 1) {
    move(p);
    ASSERT_EQ(xdo("mousedown " + std::to_string(button) + " sleep " + kPause + " mouseup " + std::to_string(button) +
                  " sleep " + kPause).status, 0);
  }
  // Presses at `from`, moves to `to` in steps, releases.
  void drag(std::pair<int, int> from, std::pair<int, int> to, int steps = 6) {
    move(from);
    ASSERT_EQ(xdo(std::string("mousedown 1 sleep ") + kPause).status, 0);
    for (int i = 1; i <= steps; ++i)
      move({from.first + (to.first - from.first) * i / steps, from.second + (to.second - from.second) * i / steps});
    ASSERT_EQ(xdo(std::string("mouseup 1 sleep ") + kPause).status, 0);
  }
  void key(const std::string& chord) { ASSERT_EQ(xdo("key " + chord + " sleep " + kPause).status, 0); }
  // (`type` takes the rest of xdotool's words as its text: the pause is a command of its own.)
  void type(const std::string& text) {
    ASSERT_EQ(xdo("type '" + text + "'").status, 0);
    ASSERT_EQ(xdo(std::string("sleep ") + kPause).status, 0);
  }

  // Lets the script go on past `wait-until STAGE`; returns the state it writes then.
  std::string stage(const std::string& name) {
    std::ofstream(path(name + ".go")) << "go\n";
    const std::string state = path(name + ".json");
    for (int i = 0; i < 2400 && !fs::exists(state); ++i) {
      if (fs::exists(path("view.status"))) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_TRUE(fs::exists(state)) << name << ": no state; the viewer said: " << read_text(path("view.out"));
    return read_text(state);
  }
  // Waits for the viewer's end; its exit status.
  int finish() {
    for (int i = 0; i < 1200 && !fs::exists(path("view.status")); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const std::string status = read_text(path("view.status"));
    return status.empty() ? -1 : std::atoi(status.c_str());
  }

  // The script's part for a stage: wait for the test's go, a few frames for the last
  // events to be drawn, the state.
  std::string script_stage(const std::string& name) const {
    return "wait-until " + path(name + ".go") + " 120\nframes 3\nstate " + path(name + ".json") + "\n";
  }

  static constexpr const char* kPause = "0.25";
  // The edit panel's places in a 1024x640 window (from its screenshot): the hole tool's
  // radio button, the region form's max-area field and its "Refine the box" button.
  static constexpr std::pair<int, int> hole_radio_{836, 136}, max_area_field_{710, 373}, refine_button_{711, 424};
  static constexpr std::pair<int, int> vertex_radio_{662, 136};
  // The right-click menu opens at the pointer: its one item ("Delete vertex N") a little
  // right of the pointer, half a line below it (its screenshot).
  static constexpr std::pair<int, int> menu_item_offset_{40, 8};
  fs::path dir_;
  std::string display_, window_;
  pid_t xvfb_ = 0, viewer_ = 0;
};

// A 4 x 3 rectangle, the input edited.
constexpr const char* kRectangle =
    "4 2 0 0\n1 0 0\n2 4 0\n3 4 3\n4 0 3\n"
    "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
    "0\n";

// E, then the segment tool's clicks close a triangle inside the rectangle; a drag moves its
// apex; Ctrl+Z puts it back exactly and Ctrl+Shift+Z moves it again; the hole tool puts a
// hole in the triangle; B and a dragged box, a bound typed into the form and "Refine the
// box" refine a region; Ctrl+S saves at each stage. Every count, coordinate and recipe is
// checked against what the pointer did, in the camera's numbers.
TEST_P(WorkbenchXEvents, RealMouseAndKeysEditUndoRedoHoleRegionAndSave) {
  const std::string input = path("rect.poly");
  std::ofstream(input) << kRectangle;
  std::string script;
  for (const char* s : {"s0", "s1", "s2", "s3", "s4", "s5", "s6"}) script += script_stage(s);
  start(input, script + "save-recipe " + path("rect.recipe") + "\nscreenshot " + path("xevents.png") + "\nquit\n");
  if (HasFatalFailure()) return;

  // E: edit mode, the input's four corners and sides.
  key("e");
  const std::string s0 = stage("s0");
  EXPECT_TRUE(has(s0, "\"editing\": true")) << s0;
  EXPECT_EQ(counts(s0), "4 4 0 0") << s0;
  const View view(s0);
  ASSERT_GT(view.scale, 10.0) << s0;

  // The segment tool (the default): three clicks and a fourth on the first vertex close a
  // triangle. Ctrl+S saves it over the input.
  const auto a = view.pixel(1, 1), b = view.pixel(3, 1), c = view.pixel(2, 2.5);
  for (const auto& p : {a, b, c, a}) click(p);
  key("ctrl+s");
  const std::string s1 = stage("s1");
  EXPECT_EQ(counts(s1), "7 7 0 0") << s1;
  const Pslg drawn = io::read_poly(input);
  ASSERT_EQ(drawn.points.size(), 7u);
  const auto expect_at = [&](const Point& p, std::pair<int, int> pixel, const char* what) {
    const Point w = view.world(pixel.first, pixel.second);
    EXPECT_NEAR(p.x, w.x, 1e-6) << what;
    EXPECT_NEAR(p.y, w.y, 1e-6) << what;
  };
  expect_at(drawn.points[4], a, "first click");
  expect_at(drawn.points[5], b, "second click");
  expect_at(drawn.points[6], c, "third click");

  // The apex dragged 40 pixels right and 30 up: one edit.
  const std::pair<int, int> moved{c.first + 40, c.second - 30};
  drag(c, moved);
  key("ctrl+s");
  const std::string s2 = stage("s2");
  EXPECT_EQ(counts(s2), "7 7 0 0") << s2;
  EXPECT_EQ(field(s2, "undo_depth"), field(s1, "undo_depth") + 1) << s2;
  const Pslg dragged = io::read_poly(input);
  expect_at(dragged.points[6], moved, "the apex dragged");
  EXPECT_EQ(dragged.points[4], drawn.points[4]);

  // Ctrl+Z: the apex back, bit for bit; Ctrl+Shift+Z: moved again, bit for bit.
  key("ctrl+z");
  key("ctrl+s");
  const std::string s3 = stage("s3");
  EXPECT_EQ(field(s3, "undo_depth"), field(s1, "undo_depth")) << s3;
  EXPECT_EQ(io::read_poly(input).points[6], drawn.points[6]);
  key("ctrl+shift+z");
  key("ctrl+s");
  const std::string s4 = stage("s4");
  EXPECT_EQ(field(s4, "undo_depth"), field(s2, "undo_depth")) << s4;
  EXPECT_EQ(io::read_poly(input).points[6], dragged.points[6]);

  // The hole tool (the panel's radio button), a click inside the triangle.
  click(hole_radio_);
  const Point apex = view.world(moved.first, moved.second);
  click(view.pixel((1 + 3 + apex.x) / 3, (1 + 1 + apex.y) / 3));
  key("ctrl+s");
  const std::string s5 = stage("s5");
  EXPECT_EQ(counts(s5), "7 7 1 0") << s5;
  EXPECT_TRUE(has(s5, "\"refusal\": null")) << s5;
  EXPECT_TRUE(has(s5, "\"input_notices\": []")) << s5;  // the hole removes the triangle's inside
  const Result t = run(std::string(MESHSTEP_BINARY) + " triangulate " + input + " -o " + path("holed") + " -q");
  ASSERT_EQ(t.status, 0) << t.output;
  EXPECT_EQ(static_cast<long long>(io::read_mesh(path("holed")).triangles.size()), field(s5, "mesh_triangles")) << s5;

  // B, a box dragged over the rectangle's right part, 0.05 typed as the form's max area,
  // "Refine the box".
  key("b");
  const auto low = view.pixel(3.2, 0.3), high = view.pixel(3.8, 2.7);
  drag({low.first, high.second}, {high.first, low.second});
  click(max_area_field_);
  type("0.05");
  click(refine_button_);
  const std::string s6 = stage("s6");
  const Point box_low = view.world(low.first, low.second), box_high = view.world(high.first, high.second);
  const std::string recipe_at = "\"recipe\": [\"refine --algorithm circumcenter --max-area 0.05 --region ";
  ASSERT_TRUE(has(s6, recipe_at)) << s6;
  double corners[4] = {0, 0, 0, 0};
  std::sscanf(s6.c_str() + s6.find(recipe_at) + recipe_at.size(), "%lf,%lf,%lf,%lf", &corners[0], &corners[1],
              &corners[2], &corners[3]);
  EXPECT_NEAR(corners[0], box_low.x, 1e-6) << s6;
  EXPECT_NEAR(corners[1], box_low.y, 1e-6) << s6;
  EXPECT_NEAR(corners[2], box_high.x, 1e-6) << s6;
  EXPECT_NEAR(corners[3], box_high.y, 1e-6) << s6;
  EXPECT_GT(field(s6, "mesh_triangles"), field(s5, "mesh_triangles") + 20) << s6;

  ASSERT_EQ(finish(), 0) << read_text(path("view.out"));
  // The saved recipe and input give the window's mesh through `meshstep run`.
  const Result m = run(std::string(MESHSTEP_BINARY) + " run " + path("rect.recipe") + " " + input + " -o " +
                       path("reproduced") + " -q");
  ASSERT_EQ(m.status, 0) << m.output << read_text(path("rect.recipe"));
  EXPECT_EQ(static_cast<long long>(io::read_mesh(path("reproduced")).triangles.size()), field(s6, "mesh_triangles"));
  EXPECT_EQ(scene::read_png(path("xevents.png")).width, 1024);
}

// The vertex tool with the real pointer: a click on empty canvas makes a vertex where the
// pointer is; a drag moves it (one edit), Ctrl+Z puts it back bit for bit and Ctrl+Shift+Z
// moves it again; the right-click menu's Delete deletes it, and Ctrl+Z brings it back
// where it was dragged to, bit for bit. Each stage saved (Ctrl+S) and read back.
TEST_P(WorkbenchXEvents, TheVertexToolAddsDragsUndoesAndDeletesFromTheMenu) {
  const std::string input = path("rect.poly");
  std::ofstream(input) << kRectangle;
  std::string script;
  for (const char* s : {"s0", "s1", "s2", "s3", "s4", "s5", "s6"}) script += script_stage(s);
  start(input, script + "screenshot " + path("vertex.png") + "\nquit\n");
  if (HasFatalFailure()) return;
  key("e");
  const std::string s0 = stage("s0");
  EXPECT_EQ(counts(s0), "4 4 0 0") << s0;
  const View view(s0);
  ASSERT_GT(view.scale, 10.0) << s0;

  // The vertex tool (the panel's first radio button), a click inside the rectangle.
  click(vertex_radio_);
  const auto at = view.pixel(1.5, 1.2);
  click(at);
  key("ctrl+s");
  const std::string s1 = stage("s1");
  EXPECT_TRUE(has(s1, "\"edit_tool\": \"vertex\"")) << s1;
  EXPECT_EQ(counts(s1), "5 4 0 0") << s1;
  const Pslg added = io::read_poly(input);
  ASSERT_EQ(added.points.size(), 5u);
  const Point w = view.world(at.first, at.second);
  EXPECT_NEAR(added.points[4].x, w.x, 1e-6);
  EXPECT_NEAR(added.points[4].y, w.y, 1e-6);

  // Dragged 35 pixels right and 25 up: one edit, the vertex where the button was released.
  const std::pair<int, int> moved{at.first + 35, at.second - 25};
  drag(at, moved);
  key("ctrl+s");
  const std::string s2 = stage("s2");
  EXPECT_EQ(counts(s2), "5 4 0 0") << s2;
  EXPECT_EQ(field(s2, "undo_depth"), field(s1, "undo_depth") + 1) << s2;
  const Pslg dragged = io::read_poly(input);
  ASSERT_EQ(dragged.points.size(), 5u);
  const Point m = view.world(moved.first, moved.second);
  EXPECT_NEAR(dragged.points[4].x, m.x, 1e-6);
  EXPECT_NEAR(dragged.points[4].y, m.y, 1e-6);
  EXPECT_NE(dragged.points[4], added.points[4]);

  // Ctrl+Z: where the click put it, bit for bit; Ctrl+Shift+Z: where the drag put it.
  key("ctrl+z");
  key("ctrl+s");
  const std::string s3 = stage("s3");
  EXPECT_EQ(field(s3, "undo_depth"), field(s1, "undo_depth")) << s3;
  EXPECT_EQ(io::read_poly(input).points.at(4), added.points[4]);
  key("ctrl+shift+z");
  key("ctrl+s");
  const std::string s4 = stage("s4");
  EXPECT_EQ(field(s4, "undo_depth"), field(s2, "undo_depth")) << s4;
  EXPECT_EQ(io::read_poly(input).points.at(4), dragged.points[4]);

  // A right click on it opens the menu; its Delete deletes it (the rectangle's corners and
  // sides stay).
  click(moved, 3);
  click({moved.first + menu_item_offset_.first, moved.second + menu_item_offset_.second});
  key("ctrl+s");
  const std::string s5 = stage("s5");
  EXPECT_EQ(counts(s5), "4 4 0 0") << s5;
  const Pslg deleted = io::read_poly(input);
  ASSERT_EQ(deleted.points.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(deleted.points[i], added.points[i]) << "corner " << i;

  // Ctrl+Z: back where it was dragged to, bit for bit.
  key("ctrl+z");
  key("ctrl+s");
  const std::string s6 = stage("s6");
  EXPECT_EQ(counts(s6), "5 4 0 0") << s6;
  EXPECT_EQ(io::read_poly(input).points.at(4), dragged.points[4]);
  ASSERT_EQ(finish(), 0) << read_text(path("view.out"));
  EXPECT_EQ(scene::read_png(path("vertex.png")).width, 1024);
}

// Shift+B and a lasso drawn with the real pointer (press, 24 moves round an ellipse,
// release): the lasso's first vertex is where the button went down, every vertex is on the
// path, and "Refine the lasso" puts exactly those vertices into the recipe.
TEST_P(WorkbenchXEvents, ARealPointerDrawsALasso) {
  const std::string input = path("rect.poly");
  std::ofstream(input) << kRectangle;
  start(input, script_stage("s0") + script_stage("s1") + script_stage("s2") + "quit\n");
  if (HasFatalFailure()) return;
  key("e");
  const View view(stage("s0"));
  key("shift+b");
  // Round (2, 1.5), radii 1.2 and 0.9 in world units, from its right end.
  const auto at = [&](int i) {
    const double t = 2 * M_PI * i / 24;
    return view.pixel(2 + 1.2 * std::cos(t), 1.5 + 0.9 * std::sin(t));
  };
  move(at(0));
  ASSERT_EQ(xdo(std::string("mousedown 1 sleep ") + kPause).status, 0);
  for (int i = 1; i <= 23; ++i) move(at(i));
  ASSERT_EQ(xdo(std::string("mouseup 1 sleep ") + kPause).status, 0);
  const std::string s1 = stage("s1");
  EXPECT_TRUE(has(s1, "\"edit_tool\": \"box lasso\"")) << s1;
  const auto lasso = s1.find("\"drawn_region\": {\"lasso\": [");
  ASSERT_NE(lasso, std::string::npos) << s1;
  std::vector<Point> ring;
  for (std::size_t i = s1.find('[', lasso + 20) + 1; s1[i] == '['; i = s1.find('[', i + 1)) {
    Point p;
    ASSERT_EQ(std::sscanf(s1.c_str() + i, "[%lf, %lf]", &p.x, &p.y), 2);
    ring.push_back(p);
    i = s1.find(']', i);
    if (s1[i + 1] == ']') break;
  }
  // The 24 corners of the path drawn: at most 24 vertices, at least the 8 an ellipse this
  // size keeps within a pixel; each one of the pixels the pointer went to (to the rounding
  // of a tenth of a pixel), the first the press.
  EXPECT_GE(ring.size(), 8u) << s1;
  EXPECT_LE(ring.size(), 24u) << s1;
  const double pixel = 1.0 / view.scale;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    double nearest = 1e300;
    for (int i = 0; i < 24; ++i) {
      const Point w = view.world(at(i).first, at(i).second);
      nearest = std::min(nearest, std::hypot(w.x - ring[k].x, w.y - ring[k].y));
    }
    EXPECT_LE(nearest, 0.1 * pixel) << "vertex " << k;
  }
  const Point press = view.world(at(0).first, at(0).second);
  EXPECT_NEAR(ring.front().x, press.x, 0.1 * pixel);
  EXPECT_NEAR(ring.front().y, press.y, 0.1 * pixel);

  click(refine_button_);
  const std::string s2 = stage("s2");
  std::string polygon;
  for (const Point& p : ring) polygon += (polygon.empty() ? "" : ",") + io::shortest_text(p.x) + "," + io::shortest_text(p.y);
  EXPECT_TRUE(has(s2, "\"recipe\": [\"refine --algorithm circumcenter --region-polygon " + polygon + "\"]")) << s2;
  ASSERT_EQ(finish(), 0) << read_text(path("view.out"));
}

INSTANTIATE_TEST_SUITE_P(Modes, WorkbenchXEvents, ::testing::Values("window"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace meshstep::viewer
