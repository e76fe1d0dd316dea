// The viewer program driven by scripts: off screen on EGL and on OSMesa, and in a real
// window under xvfb-run. Each run's state is checked exactly against the log, and its
// window screenshot against tests/golden/viewer_lesson.png (the renderer's tolerance: 5
// per channel on at most 0.1% of the pixels). Update the golden on purpose with
// MESHSTEP_UPDATE_GOLDENS=1 build/tests/viewer/meshstep_viewer_tests, then look at it.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "program_support.hpp"
#include "golden_runs.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/image.hpp"

namespace meshstep::viewer {
namespace {

using testing::field;
using testing::frame_allocations;
using testing::has;
using testing::read_text;
using testing::Result;
using testing::run;

namespace fs = std::filesystem;

constexpr const char* kOffcenter = "--algorithm offcenter --min-angle 30";





class ViewerProgram : public testing::ScriptedViewer {
 protected:
  ViewerProgram() : ScriptedViewer("viewer_program", "1024x640") {}
  void SetUp() override {
    ScriptedViewer::SetUp();
    log_ = golden::lesson_run(kOffcenter);
    ASSERT_NE(log_, nullptr);
  }
};

TEST_P(ViewerProgram, KeysMoveTheCursorAndChangeWhatIsShown) {
  const std::string a = (dir_ / "a.json").string(), b = (dir_ / "b.json").string();
  VIEW_OR_SKIP(r,
               "seek step 47\nframes 2\nstate " + a +
                   "\nkey Right\nkey Shift+Left\nkey C\nkey F3\nkey Ctrl+2\nkey Home\nkey 2\nkey ?\nstate " + b +
                   "\nquit\n");
  const std::string before = read_text(a), after = read_text(b);
  EXPECT_EQ(field(before, "position"), static_cast<long long>(log_->step_start(47)));
  EXPECT_EQ(field(before, "step"), 47);
  EXPECT_TRUE(has(before, "\"explain_heading\": \"step 47 of ")) << before;
  EXPECT_TRUE(has(before, "\"caption\": \"refine \u00B7 step 47 of ")) << before;
  // The pseudo-code panel follows the run: an off-center refinement, and step 47 ends in
  // the insertion's Lawson flips (in-circle tests), as its explanation says.
  EXPECT_TRUE(has(before, "\"code_title\": \"Off-center refinement")) << before;
  EXPECT_TRUE(has(before, "Lawson flips")) << before;
  EXPECT_TRUE(has(before, "\"code_line\": \"") && has(before, "in-circle")) << before;
  // Right: to the end of step 48; Shift+Left: one event back, inside it.
  const long long inside = static_cast<long long>(log_->step_start(48)) - 1;
  EXPECT_EQ(field(after, "bookmarks\": {\"2"), inside) << after;  // Ctrl+2 set there
  EXPECT_EQ(field(after, "position"), inside) << "Home, then 2 went back to the bookmark";
  EXPECT_TRUE(has(after, "\"color_by\": \"angle\"")) << after;
  EXPECT_FALSE(has(after, "\"edges\"")) << "F3 switches the edges off: " << after;
  EXPECT_TRUE(has(after, "\"help_open\": true")) << after;
}

// One step number (issue 29): inside step 47 (one event before its end) the state's step,
// which the timeline prints, is the caption's and the explanation's step, 47.
TEST_P(ViewerProgram, CaptionTimelineAndExplanationSayTheSameStep) {
  const std::string a = (dir_ / "a.json").string(), b = (dir_ / "b.json").string();
  VIEW_OR_SKIP(r, "seek step 47\nkey Shift+Left\nframes 1\nstate " + a + "\nseek step 0\nframes 1\nstate " + b +
                      "\nquit\n");
  const std::string inside = read_text(a), start = read_text(b);
  EXPECT_EQ(field(inside, "position"), static_cast<long long>(log_->step_start(47)) - 1);
  EXPECT_EQ(field(inside, "step"), 47) << inside;
  EXPECT_TRUE(has(inside, "\"in_step\": true")) << inside;
  EXPECT_TRUE(has(inside, "\"caption\": \"refine \u00B7 step 47 of ")) << inside;
  EXPECT_TRUE(has(inside, "\"explain_heading\": \"step 47 of ")) << inside;
  EXPECT_EQ(field(start, "step"), 0) << start;
  EXPECT_EQ(field(start, "position"), static_cast<long long>(log_->step_start(0))) << start;
}

// `+` doubles the speed as `=` does (on most keyboards `+` is Shift+=); `-` halves it.
TEST_P(ViewerProgram, PlusAndEqualsBothDoubleTheSpeed) {
  const std::string a = (dir_ / "a.json").string(), b = (dir_ / "b.json").string(), c = (dir_ / "c.json").string();
  VIEW_OR_SKIP(r, "speed 2\nkey +\nstate " + a + "\nkey =\nstate " + b + "\nkey -\nstate " + c + "\nquit\n");
  EXPECT_TRUE(has(read_text(a), "\"speed\": 4,")) << read_text(a);
  EXPECT_TRUE(has(read_text(b), "\"speed\": 8,")) << read_text(b);
  EXPECT_TRUE(has(read_text(c), "\"speed\": 4,")) << read_text(c);
}

TEST_P(ViewerProgram, PlaysAtTheScriptsFixedFrameTime) {
  const std::string a = (dir_ / "a.json").string();
  VIEW_OR_SKIP(r, "seek step 10\nspeed 30\nplay 30\nstate " + a + "\nquit\n");
  const std::string s = read_text(a);
  EXPECT_EQ(field(s, "step"), 40) << "30 frames of 1/30 s at 30 steps per second";
  EXPECT_TRUE(has(s, "\"playing\": false")) << s;
}

TEST_P(ViewerProgram, DragPansWheelZoomsAndTheTimelineScrubs) {
  const std::string a = (dir_ / "a.json").string(), b = (dir_ / "b.json").string(),
                    c = (dir_ / "c.json").string();
  // The canvas is the window's left part above the timeline; the bar is the bottom strip.
  VIEW_OR_SKIP(r, "frames 2\nstate " + a + "\nmouse 300 250\ndrag 120 0\nwheel 3\nframes 1\nstate " + b +
                      "\nmouse 322 625\nclick\nframes 1\nstate " + c + "\nquit\n");
  const std::string before = read_text(a), after = read_text(b), scrubbed = read_text(c);
  const auto number = [](const std::string& json, const char* key) {
    const auto at = json.find(std::string("\"") + key + "\": ");
    return at == std::string::npos ? NAN : std::atof(json.c_str() + at + std::strlen(key) + 4);
  };
  EXPECT_GT(number(after, "pixels_per_unit"), 1.5 * number(before, "pixels_per_unit")) << after;
  EXPECT_NE(number(after, "x"), number(before, "x")) << after;
  // A click half way along the bar seeks to about the middle of the run.
  const double fraction = static_cast<double>(field(scrubbed, "position")) / static_cast<double>(log_->event_count());
  EXPECT_GT(fraction, 0.3) << scrubbed;
  EXPECT_LT(fraction, 0.7) << scrubbed;
}

// An idle viewer's frames allocate nothing (C++ and ImGui allocations, counted by the
// program's own operator new), and the frame that follows a change does.
TEST_P(ViewerProgram, IdleFramesDoNotAllocate) {
  const fs::path frames = dir_ / "frames.txt";
  VIEW_OR_SKIP(r, "seek step 45\nframes 6\nkey C\nframes 20\nquit\n", "--frame-log " + frames.string());
  const std::vector<unsigned long long> allocations = frame_allocations(frames);
  ASSERT_GE(allocations.size(), 25u);
  // Under the sanitizers only ImGui's allocations are counted: the frames that must
  // allocate may not show it, the idle ones must still count nothing.
  const bool counts_new = MESHSTEP_VIEW_COUNTS_NEW;
  if (counts_new) {
    EXPECT_GT(allocations[0], 0u) << "the first frame builds everything";
  }
  // Frames 0 and 1 warm up (ImGui sizes its buffers over its first two frames); 2-5 idle;
  // 6 presses C (a new colouring: a new scene); 7 releases it; then idle.
  for (std::size_t i = 2; i < 6; ++i) EXPECT_EQ(allocations[i], 0u) << "idle frame " << i;
  if (counts_new) {
    EXPECT_GT(allocations[6], 0u) << "the frame of the new colouring";
  }
  for (std::size_t i = 8; i < allocations.size(); ++i) EXPECT_EQ(allocations[i], 0u) << "idle frame " << i;
}

TEST_P(ViewerProgram, WindowScreenshotMatchesItsGolden) {
  const fs::path shot = dir_ / "shot.png";
  VIEW_OR_SKIP(r, "seek step 47\nframes 3\nscreenshot " + shot.string() + "\nquit\n");
  const scene::Image actual = scene::read_png(shot.string());
  ASSERT_EQ(actual.width, 1024);
  ASSERT_EQ(actual.height, 640);
  const fs::path golden = fs::path(MESHSTEP_GOLDEN_DIR) / "viewer_lesson.png";
  if (std::getenv("MESHSTEP_UPDATE_GOLDENS") && GetParam() == "egl") {
    scene::write_png(golden.string(), actual, 9);
    GTEST_SKIP() << "updated " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing: run with MESHSTEP_UPDATE_GOLDENS=1 and look at it";
  const scene::ImageDiff diff = scene::compare_images(scene::read_png(golden.string()), actual, 5);
  const std::size_t allowed = static_cast<std::size_t>(actual.width) * static_cast<std::size_t>(actual.height) / 1000;
  if (!diff.same_size || diff.differing_pixels > allowed) {
    fs::create_directories(MESHSTEP_GOLDEN_OUT);
    const std::string stem = std::string(MESHSTEP_GOLDEN_OUT) + "/viewer_lesson." + GetParam();
    scene::write_png(stem + ".actual.png", actual);
    if (diff.same_size) scene::write_png(stem + ".diff.png", diff.picture);
    ADD_FAILURE() << diff.differing_pixels << " pixels differ by more than 5 (allowed " << allowed << "); see " << stem
                  << ".actual.png and .diff.png";
  }
  // A different moment is a different picture: the comparison can fail.
  const fs::path other = dir_ / "other.png";
  VIEW_OR_SKIP(r2, "seek step 20\nframes 3\nscreenshot " + other.string() + "\nquit\n");
  EXPECT_GT(scene::compare_images(actual, scene::read_png(other.string()), 5).differing_pixels, allowed);
}

// With the canvas drawn by a worker thread (as for runs of more than 20,000 vertices), a
// script sees the same moment, words and window as with the canvas drawn on the main
// thread; and once the worker's picture is in, idle frames allocate nothing.
TEST_P(ViewerProgram, WorkerCanvasShowsTheSameMomentAndWindow) {
  const fs::path frames = dir_ / "frames.txt";
  const auto script = [&](const std::string& name) {
    return "seek step 45\nframes 3\nstate " + (dir_ / (name + "45.json")).string() + "\nscreenshot " +
           (dir_ / (name + ".png")).string() + "\nseek step 20\nstate " + (dir_ / (name + "20.json")).string() +
           "\nframes 20\nquit\n";
  };
  VIEW_OR_SKIP(r, script("worker"), "--canvas worker --frame-log " + frames.string());
  VIEW_OR_SKIP(m, script("main"), "--canvas main");
  const std::string at45 = read_text(dir_ / "worker45.json"), at20 = read_text(dir_ / "worker20.json");
  EXPECT_TRUE(has(at45, "\"canvas\": \"worker\"")) << at45;
  EXPECT_TRUE(has(read_text(dir_ / "main45.json"), "\"canvas\": \"main\""));
  EXPECT_EQ(field(at45, "position"), static_cast<long long>(log_->step_start(45)));
  EXPECT_EQ(field(at45, "shown_position"), static_cast<long long>(log_->step_start(45)));
  EXPECT_EQ(field(at20, "shown_position"), static_cast<long long>(log_->step_start(20)));
  // The words, the caption and the statistics are those of the main thread's run.
  const auto from = [](const std::string& json, const std::string& key) {
    const auto at = json.find("\"" + key + "\"");
    return at == std::string::npos ? std::string() : json.substr(at, json.find('\n', at) - at);
  };
  for (const char* key : {"caption", "explain_heading", "code_line", "stats", "camera"}) {
    EXPECT_EQ(from(at45, key), from(read_text(dir_ / "main45.json"), key)) << key;
    EXPECT_EQ(from(at20, key), from(read_text(dir_ / "main20.json"), key)) << key;
  }
  EXPECT_TRUE(has(at20, "\"caption\": \"recover segments \u00B7 step 20 of ")) << at20;

  // The same window, pixel for pixel within the golden tolerance.
  const scene::Image worker = scene::read_png((dir_ / "worker.png").string());
  const scene::Image main = scene::read_png((dir_ / "main.png").string());
  const scene::ImageDiff diff = scene::compare_images(main, worker, 5);
  EXPECT_TRUE(diff.same_size);
  EXPECT_LE(diff.differing_pixels, static_cast<std::size_t>(worker.width) * worker.height / 1000);

  // The last 15 frames come after the picture of step 20 was taken in: idle.
  std::ifstream in(frames);
  std::vector<unsigned long long> allocations;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    unsigned long long index = 0, count = 0;
    double end_ms = 0, frame_ms = 0;
    f >> index >> end_ms >> frame_ms >> count;
    allocations.push_back(count);
  }
  ASSERT_GE(allocations.size(), 24u);
  for (std::size_t i = allocations.size() - 15; i < allocations.size(); ++i)
    EXPECT_EQ(allocations[i], 0u) << "idle frame " << i;
}

INSTANTIATE_TEST_SUITE_P(Modes, ViewerProgram, ::testing::Values("egl", "osmesa", "window"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// Issue 31: --frame-log that is the log itself (here a hard link to it) is refused before
// the viewer opens anything, and the log is left as it was.
TEST(ViewerFrameLog, RefusesToWriteOverTheInput) {
  const fs::path dir = fs::temp_directory_path() / ("viewer_frame_log_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const replay::LogReader* golden_log = golden::lesson_run(kOffcenter);
  ASSERT_NE(golden_log, nullptr);
  const fs::path log = dir / "run.mslog", link = dir / "frames.txt", script = dir / "quit.txt";
  fs::copy_file(golden_log->path(), log);
  fs::create_hard_link(log, link);
  std::ofstream(script) << "quit\n";
  const std::string before = read_text(log);
  const Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log.string() + " --offscreen -q --script " +
                       script.string() + " --frame-log " + link.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r.output, "--frame-log " + link.string() + " would overwrite the input " + log.string())) << r.output;
  EXPECT_EQ(read_text(log), before);
  fs::remove_all(dir);
}

// "Check every step" in the viewer: an off-center run holds at every boundary; a
// Lepp-bisection run (bisection makes no flips) breaks Delaunay at a bisection step.
TEST(ViewerInvariants, ChecksEveryStepAndNamesTheOneThatBreaks) {
  const fs::path dir = fs::temp_directory_path() / ("viewer_invariants_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path script = dir / "check.txt", state = dir / "state.json";
  std::ofstream(script) << "check\nstate " << state.string() << "\nquit\n";
  for (const char* args : {kOffcenter, "--algorithm lepp-bisection --max-area 0.5"}) {
    const replay::LogReader* log = golden::lesson_run(args);
    ASSERT_NE(log, nullptr);
    const Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen -q --script " +
                         script.string());
    if (r.status != 0 && has(r.output, "cannot open a window or draw")) GTEST_SKIP() << r.output;
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string json = read_text(state);
    if (std::string(args) == kOffcenter) {
      EXPECT_TRUE(has(json, "hold at the " + std::to_string(log->step_count() + 1) + " step boundaries")) << json;
    } else {
      const std::string tag = "\"invariants\": \"step ";
      const auto at = json.find(tag);
      ASSERT_NE(at, std::string::npos) << json;
      const long long step = std::atoll(json.c_str() + at + tag.size());
      ASSERT_GT(step, 0) << json;
      EXPECT_TRUE(has(json, "breaks delaunay")) << json;
      EXPECT_EQ(log->step_kind(static_cast<std::uint64_t>(step - 1)), replay::StepKind::bisect) << json;
    }
  }
  fs::remove_all(dir);
}

// The inspector: a vertex is named with the step that inserted it; a triangle with its
// angles, its Lepp path; a selected triangle stays selected while it exists.
TEST(ViewerInspector, SelectsVerticesAndTriangles) {
  const replay::LogReader* log = golden::lesson_run(kOffcenter);
  ASSERT_NE(log, nullptr);
  // The vertex step 47 inserted (0-based step 46; a refine step, the off-center run's 45th and 46th
  // being segment splits), and a triangle of the mesh after it.
  const std::uint64_t inputs = log->run().input_vertices;
  std::uint32_t vertex = kNone;
  for (std::uint32_t v = 0; v < log->vertices().size(); ++v)
    if (log->vertices()[v].event != kNone && log->step_of_event(log->vertices()[v].event) == 46 &&
        log->vertices()[v].input_index >= inputs)
      vertex = v;
  ASSERT_NE(vertex, kNone);
  replay::Replay cursor(*log);
  cursor.seek_step(47);
  const TriMesh mesh = cursor.mesh();
  ASSERT_FALSE(mesh.triangles.empty());
  const auto& t = mesh.triangles.front();
  const Point c{(mesh.points[t[0]].x + mesh.points[t[1]].x + mesh.points[t[2]].x) / 3,
                (mesh.points[t[0]].y + mesh.points[t[1]].y + mesh.points[t[2]].y) / 3};
  // The mesh's points are numbered as the log numbers vertices only for the cursor's
  // vertices; the triangle is named by its log ids: look them up by position.
  std::vector<std::uint32_t> ids;
  for (const std::uint32_t i : t)
    for (std::uint32_t v = 0; v < log->vertices().size(); ++v)
      if (log->vertices()[v].event != kNone && log->vertices()[v].point == mesh.points[i]) {
        ids.push_back(v);
        break;
      }
  ASSERT_EQ(ids.size(), 3u);

  const fs::path dir = fs::temp_directory_path() / ("viewer_inspector_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path script = dir / "s.txt", a = dir / "a.json", b = dir / "b.json";
  char line[256];
  std::snprintf(line, sizeof line, "seek step 47\nwait\nselect %.17g %.17g\nframes 1\nstate %s\nselect %.17g %.17g\nframes 1\nstate %s\nquit\n",
                log->vertices()[vertex].point.x, log->vertices()[vertex].point.y, a.c_str(), c.x, c.y, b.c_str());
  std::ofstream(script) << line;
  const Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen -q --script " + script.string());
  if (r.status != 0 && has(r.output, "cannot open a window or draw")) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string vs = read_text(a), ts = read_text(b);
  // Named by its number in the output's .node, as every text names it, not by its log id.
  EXPECT_TRUE(has(vs, "\"selection\": \"vertex " + log->vertex_name(vertex) + " at")) << vs;
  EXPECT_TRUE(has(vs, "Steiner, inserted by step 47 (refine)")) << vs;
  // Its history: step 47 first, then every step whose mesh-changing events name it.
  std::vector<std::uint64_t> expected;
  for (std::uint64_t e = 0; e < log->event_count(); ++e) {
    const replay::Event ev = log->event(e);
    const replay::EventSchema& schema = replay::schema(ev.type);
    bool names = false;
    for (std::size_t i = 0; i < schema.id_count; ++i)
      names = names || (schema.id_kinds[i] == replay::IdKind::vertex && ev.ids[i] == vertex);
    const std::uint64_t step = log->step_of_event(e) + 1;
    if (schema.changes_mesh() && names && (expected.empty() || expected.back() != step)) expected.push_back(step);
  }
  std::string list = "[";
  for (const std::uint64_t k : expected) list += (list.size() > 1 ? ", " : "") + std::to_string(k);
  ASSERT_GE(expected.size(), 2u);
  EXPECT_EQ(expected.front(), 47u);
  EXPECT_TRUE(has(vs, "\"selection_history\": " + list + "]")) << list << "] in " << vs;
  EXPECT_TRUE(has(ts, "\"selection\": \"triangle ")) << ts;
  for (const std::uint32_t id : ids) {
    const std::string name = std::string(1, ' ').append(std::to_string(id));
    EXPECT_TRUE(has(ts, name)) << id << " in " << ts;
  }
  EXPECT_TRUE(has(ts, "Lepp path of ")) << ts;
  fs::remove_all(dir);
}

// A triangle's region: a .poly whose middle segment splits two regions, refined by the
// command line with --record (which keeps the region points in the log), then a click on
// each side. The later region point of each side wins, as in the written mesh.
TEST(ViewerInspector, SaysATrianglesRegion) {
  const fs::path dir = fs::temp_directory_path() / ("viewer_regions_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path poly = dir / "halves.poly", log = dir / "halves.mslog", script = dir / "s.txt";
  const fs::path left = dir / "left.json", right = dir / "right.json";
  std::ofstream(poly) << "6 2 0 0\n1 0 0\n2 2 0\n3 4 0\n4 4 4\n5 2 4\n6 0 4\n"
                         "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n0\n"
                         "3\n1 1 3 7 -1\n2 1 2 1 -1\n3 3 1 5 -1\n";
  const Result recorded = run(std::string(MESHSTEP_BINARY) + " refine " + poly.string() + " --min-angle 25 -q --record " +
                              log.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(recorded.status, 0) << recorded.output;
  const Result info = run(std::string(MESHSTEP_BINARY) + " log info " + log.string());
  EXPECT_TRUE(has(info.output, "regions:    3 region points")) << info.output;
  // On each side, the centroid of the final triangle farthest from every vertex: a click
  // there picks that triangle.
  const replay::LogReader reader(log.string());
  replay::Replay cursor(reader);
  cursor.seek_event(reader.event_count());
  const auto& v = reader.vertices();
  Point click[2];
  double clearance[2] = {-1, -1};
  for (const replay::FaceRecord& f : cursor.slots()) {
    if (f.dead() || f.ghost()) continue;
    const Point c{(v[f.v[0]].point.x + v[f.v[1]].point.x + v[f.v[2]].point.x) / 3,
                  (v[f.v[0]].point.y + v[f.v[1]].point.y + v[f.v[2]].point.y) / 3};
    double nearest = INFINITY;
    for (const replay::VertexInfo& info : v) nearest = std::min(nearest, std::hypot(info.point.x - c.x, info.point.y - c.y));
    const int side = c.x < 2 ? 0 : 1;
    if (nearest > clearance[side]) clearance[side] = nearest, click[side] = c;
  }
  ASSERT_GT(clearance[0], 0);
  ASSERT_GT(clearance[1], 0);
  char text[256];
  std::snprintf(text, sizeof text, "seek end\nwait\nselect %.17g %.17g\nframes 1\nstate %s\nselect %.17g %.17g\nframes 1\nstate %s\nquit\n",
                click[0].x, click[0].y, left.c_str(), click[1].x, click[1].y, right.c_str());
  std::ofstream(script) << text;
  const Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log.string() + " --offscreen -q --script " + script.string());
  if (r.status != 0 && has(r.output, "cannot open a window or draw")) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string ls = read_text(left), rs = read_text(right);
  EXPECT_TRUE(has(ls, "\"selection\": \"triangle ") && has(ls, ", region 1;")) << ls;
  EXPECT_TRUE(has(rs, "\"selection\": \"triangle ") && has(rs, ", region 5;")) << rs;
  fs::remove_all(dir);
}

// The plots over the whole run agree with the mesh at the cursor, step by step.
TEST(ViewerPlots, AgreeWithTheMeshAtEveryStepLookedAt) {
  const replay::LogReader* log = golden::lesson_run(kOffcenter);
  ASSERT_NE(log, nullptr);
  const fs::path dir = fs::temp_directory_path() / ("viewer_plots_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string script = "wait\n";
  const std::vector<std::uint64_t> steps = {0, 10, 24, 45, log->step_count()};
  const auto state_file = [&](std::uint64_t k) { return dir / std::to_string(k).append(".json"); };
  for (const std::uint64_t k : steps)
    script.append("seek step ").append(std::to_string(k)).append("\nstate ").append(state_file(k).string()).append("\n");
  std::ofstream(dir / "s.txt") << script << "quit\n";
  const Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen -q --script " +
                       (dir / "s.txt").string());
  if (r.status != 0 && has(r.output, "cannot open a window or draw")) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  for (const std::uint64_t k : steps) {
    const std::string json = read_text(state_file(k));
    const auto number_after = [&](const std::string& tag) {
      const auto at = json.find(tag);
      return at == std::string::npos ? NAN : std::atof(json.c_str() + at + tag.size());
    };
    // The plots' figures (a float each) against the statistics of the scene at the cursor.
    EXPECT_EQ(number_after("\"plots_at_cursor\": {\"triangles\": "), number_after("\"triangles\": ")) << json;
    const double plotted = number_after("\"smallest_angle\": "), stats = number_after("\"min_angle\": ");
    if (number_after("\"triangles\": ") > 0) {
      EXPECT_NEAR(plotted, stats, 1e-4) << json;
    }
    EXPECT_EQ(number_after("\"steps\": "), static_cast<double>(log->step_count() + 1)) << json;
  }
  fs::remove_all(dir);
}

// Without INPUT the viewer starts on the start page: a file that cannot be opened is
// reported there, and the first example's "refine" button records and opens its run.
TEST(ViewerStartPage, OpensAnExampleOrSaysWhyNot) {
  const fs::path dir = fs::temp_directory_path() / ("viewer_start_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path script = dir / "start.txt", start = dir / "start.json", opened = dir / "opened.json";
  std::ofstream(script) << "frames 2\nopen " << (dir / "missing.mslog").string() << "\nframes 1\nstate "
                        << start.string() << "\nmouse 90 87\nclick\nframes 2\nstate " << opened.string()
                        << "\nquit\n";
  const Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " --offscreen -q --window 1280x800 --script " + script.string());
  if (r.status != 0 && has(r.output, "cannot open a window or draw")) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string page = read_text(start), run_state = read_text(opened);
  EXPECT_TRUE(has(page, "\"page\": \"start\"")) << page;
  EXPECT_TRUE(has(page, "missing.mslog: no such file")) << page;
  EXPECT_TRUE(has(run_state, "examples/lesson.poly\"")) << run_state;
  EXPECT_GT(field(run_state, "step_count"), 20) << run_state;
  EXPECT_TRUE(has(run_state, "\"code_title\": \"Off-center")) << run_state;
  fs::remove_all(dir);
}

TEST(ViewerCli, BadScriptsAndInputsSayWhereAndExitNonZero) {
  const fs::path script = fs::temp_directory_path() / ("viewer_bad_" + std::to_string(::getpid()) + ".txt");
  std::ofstream(script) << "seek step 4\nbogus 3\n";
  const replay::LogReader* log = golden::lesson_run(kOffcenter);
  ASSERT_NE(log, nullptr);
  Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen --script " + script.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(has(r.output, script.string() + ":2: unknown action 'bogus'")) << r.output;

  r = run(std::string(MESHSTEP_VIEW_BINARY) + " /nonexistent/run.mslog --offscreen");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(has(r.output, "/nonexistent/run.mslog")) << r.output;

  // A missing file is named, and said to be missing.
  r = run(std::string(MESHSTEP_VIEW_BINARY) + " /nonexistent/lesson.poly --offscreen");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(has(r.output, "/nonexistent/lesson.poly: does not exist")) << r.output;

  // A step past the run is refused in the words of every command, from the command line
  // and from a script (as the go-to box refuses it).
  const std::string n = std::to_string(log->step_count()), beyond = std::to_string(log->step_count() + 1);
  r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen --step " + beyond);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.output, "--step " + beyond + " is outside the run: its steps are numbered 0.." + n)) << r.output;
  std::ofstream(script) << "seek step " << beyond << "\nquit\n";
  r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen --script " + script.string());
  if (!has(r.output, "cannot open a window or draw")) {
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(has(r.output, ":1: seek step: ")) << r.output;
    EXPECT_TRUE(has(r.output, "step " + beyond + " is outside the run: its steps are numbered 0.." + n)) << r.output;
  }
  fs::remove(script);

  r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen --window 10x10");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.output, "--window 10x10")) << r.output;

  // `meshstep view` is the viewer: its help lists the keys.
  r = run(std::string(MESHSTEP_BINARY) + " view --help");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has(r.output, "Keys: Space play/pause")) << r.output;
}

}  // namespace
}  // namespace meshstep::viewer
