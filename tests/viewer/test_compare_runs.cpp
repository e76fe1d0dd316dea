// Runs side by side (compare_view.hpp): the difference of two meshes' edges and the sync
// rules in process, then the viewer program on two and four recorded runs (EGL, OSMesa, an
// Xvfb window), each run's cursor in the state checked against positions this file works
// out from the logs by itself, and the side-by-side window and its difference overlay
// checked by their pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "compare_sync.hpp"
#include "edge_difference.hpp"
#include "golden_runs.hpp"
#include "meshstep/scene/image.hpp"
#include "program_support.hpp"

namespace meshstep::viewer {
namespace {

using testing::field;
using testing::frame_allocations;
using testing::has;
using testing::read_text;
using testing::Result;

constexpr const char* kOffcenter = "--algorithm offcenter --min-angle 30";
constexpr const char* kCircumcenter = "--algorithm circumcenter --min-angle 30";
constexpr const char* kCavity = "--algorithm offcenter --min-angle 30 --insertion cavity";
constexpr const char* kLeppMidpoint = "--algorithm lepp-midpoint";

scene::MeshLayer mesh(std::vector<Point> points, std::vector<std::array<std::uint32_t, 3>> triangles) {
  scene::MeshLayer m;
  m.points = std::move(points);
  m.triangles = std::move(triangles);
  return m;
}

// ---- The difference of edges ---------------------------------------------------------

TEST(EdgeDifference, TheOtherDiagonalIsTheOnlyDifference) {
  // A unit square split by one diagonal, and by the other; the second numbers its points
  // in another order, which must not matter.
  const scene::MeshLayer a = mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}});
  const scene::MeshLayer b = mesh({{1, 1}, {0, 1}, {0, 0}, {1, 0}}, {{3, 0, 1}, {3, 1, 2}});
  const EdgeSet ea = edge_set(a), eb = edge_set(b);
  EXPECT_EQ(ea.edges.size(), 5u) << "four sides and a diagonal, each once";
  const auto only_a = edges_missing(ea, eb), only_b = edges_missing(eb, ea);
  ASSERT_EQ(only_a.size(), 1u);
  ASSERT_EQ(only_b.size(), 1u);
  EXPECT_EQ(only_a[0][0], (Point{0, 0}));
  EXPECT_EQ(only_a[0][1], (Point{1, 1}));
  EXPECT_EQ(only_b[0][0], (Point{0, 1}));
  EXPECT_EQ(only_b[0][1], (Point{1, 0}));
  EXPECT_TRUE(edges_missing(ea, ea).empty());
}

TEST(EdgeDifference, AStrayTriangleIsSkippedAndAnEmptyMeshLacksEverything) {
  const scene::MeshLayer a = mesh({{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 2}, {0, 1, 7}});
  EXPECT_EQ(edge_set(a).edges.size(), 3u);
  EXPECT_EQ(edges_missing(edge_set(a), edge_set(scene::MeshLayer{})).size(), 3u);
  EXPECT_TRUE(edges_missing(edge_set(scene::MeshLayer{}), edge_set(a)).empty());
}

// ---- Sync, worked out here from the logs ----------------------------------------------

// The vertices inserted after `position` events, counted one by one.
std::uint64_t count_inserted(const replay::LogReader& log, std::uint64_t position) {
  std::uint64_t n = 0;
  for (const replay::VertexInfo& v : log.vertices()) n += v.event != kNone && v.event + 1 <= position;
  return n;
}

// Where a follower stands for the leader's position, by walking its step boundaries.
std::uint64_t expected_position(const replay::LogReader& lead, std::uint64_t at, const replay::LogReader& f,
                                const std::string& mode) {
  std::uint64_t done = 0;  // the leader's completed steps: the last boundary at or before `at`
  for (std::uint64_t k = 0; k <= lead.step_count(); ++k)
    if (lead.step_start(k) <= at) done = k;
  if (at < lead.step_start(0)) done = 0;
  if (mode == "step") return f.step_start(std::min(done, f.step_count()));
  if (mode == "fraction") {
    const double share = lead.step_count() ? double(done) / double(lead.step_count()) : 0.0;
    return f.step_start(std::min<std::uint64_t>(f.step_count(), std::llround(share * double(f.step_count()))));
  }
  const std::uint64_t want = count_inserted(lead, at);
  for (std::uint64_t k = 0; k <= f.step_count(); ++k)
    if (count_inserted(f, f.step_start(k)) >= want) return f.step_start(k);
  return f.event_count();
}

TEST(CompareSync, FollowersStandWhereTheLogsSay) {
  const replay::LogReader* a = golden::lesson_run(kOffcenter);
  const replay::LogReader* b = golden::lesson_run(kLeppMidpoint);
  ASSERT_TRUE(a && b);
  ASSERT_NE(a->step_count(), b->step_count()) << "the test wants runs of different lengths";
  const replay::LogReader& lead = a->step_count() > b->step_count() ? *a : *b;
  const replay::LogReader& follow = &lead == a ? *b : *a;
  EXPECT_EQ(leading_run({a, b}), &lead == a ? 0u : 1u);
  const std::vector<std::uint64_t> insertions = insertion_events(follow), lead_insertions = insertion_events(lead);
  for (const SyncMode mode : {SyncMode::step, SyncMode::vertices, SyncMode::fraction}) {
    for (std::uint64_t k = 0; k <= lead.step_count(); ++k) {
      const std::uint64_t at = lead.step_start(k);
      ASSERT_EQ(inserted_vertices(lead_insertions, at), count_inserted(lead, at)) << k;
      ASSERT_EQ(synced_position(lead, lead_insertions, at, follow, insertions, mode), expected_position(lead, at, follow, name(mode)))
          << name(mode) << " at the leader's step " << k;
      // Inside a step too (one event before its end).
      if (at > 0) {
        ASSERT_EQ(synced_position(lead, lead_insertions, at - 1, follow, insertions, mode),
                  expected_position(lead, at - 1, follow, name(mode)))
            << name(mode) << " inside the leader's step " << k;
      }
    }
    // At its end the leader takes the follower to its own end.
    if (mode != SyncMode::vertices) {
      EXPECT_EQ(synced_position(lead, lead_insertions, lead.event_count(), follow, insertions, mode), follow.event_count())
          << name(mode);
    }
  }
  EXPECT_EQ(inserted_vertices(lead, lead.event_count()), count_inserted(lead, lead.event_count()));
  EXPECT_EQ(parse_sync_mode("vertices"), SyncMode::vertices);
  EXPECT_FALSE(parse_sync_mode("steps"));
}

TEST(CompareSync, StepsPerPhaseAddUpToTheRun) {
  const replay::LogReader* a = golden::lesson_run(kOffcenter);
  ASSERT_NE(a, nullptr);
  std::uint64_t total = 0;
  bool refine = false;
  for (const auto& [phase, steps] : steps_per_phase(*a)) {
    total += steps;
    refine = refine || phase == "refine";
  }
  EXPECT_EQ(total, a->step_count());
  EXPECT_TRUE(refine);
}

// ---- The viewer program on runs side by side ------------------------------------------

// The state's line of run i (the runs array holds one run a line).
std::string run_line(const std::string& state, std::size_t i) {
  const std::string tag = "{\"index\": " + std::to_string(i) + ",";
  const auto at = state.find(tag);
  if (at == std::string::npos) return "";
  return state.substr(at, state.find('\n', at) - at);
}

class SideBySide : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("side_by_side_" + std::to_string(::getpid()) + "_" + GetParam());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  // The viewer on these runs' logs with a script, in the mode of the parameter.
  Result view(const std::vector<const replay::LogReader*>& logs, const std::string& script, const std::string& extra = "") {
    std::string paths = logs[0]->path();
    for (std::size_t i = 1; i < logs.size(); ++i) paths += " " + logs[i]->path();
    return testing::view_log(MESHSTEP_VIEW_BINARY, paths, dir_, GetParam(), "1280x800", script, extra);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

#define SIDE_OR_SKIP(result, logs, script, ...)              \
  const Result result = view(logs, script, ##__VA_ARGS__);      \
  if (result.status == 77) GTEST_SKIP() << result.output; \
  ASSERT_EQ(result.status, 0) << result.output

// Checks every run's position in a state against the leader's, as the logs say.
void expect_synced(const std::string& state, const std::vector<const replay::LogReader*>& logs, const std::string& mode) {
  std::size_t lead = 0;
  for (std::size_t i = 1; i < logs.size(); ++i)
    if (logs[i]->step_count() > logs[lead]->step_count()) lead = i;
  const std::string lead_line = run_line(state, lead);
  ASSERT_TRUE(has(lead_line, "\"leads\": true")) << state;
  const long long at = field(lead_line, "position");
  ASSERT_GE(at, 0) << state;
  EXPECT_EQ(field(state, "position"), at) << "the top-level cursor is the leader's";
  for (std::size_t i = 0; i < logs.size(); ++i) {
    const std::string line = run_line(state, i);
    ASSERT_FALSE(line.empty()) << "run " << i << " missing: " << state;
    const std::uint64_t want = i == lead ? static_cast<std::uint64_t>(at)
                                         : expected_position(*logs[lead], static_cast<std::uint64_t>(at), *logs[i], mode);
    EXPECT_EQ(field(line, "position"), static_cast<long long>(want)) << mode << ", run " << i << ": " << line;
    EXPECT_EQ(field(line, "shown_position"), static_cast<long long>(want)) << "its canvas shows it: " << line;
    EXPECT_EQ(field(line, "inserted_vertices"), static_cast<long long>(count_inserted(*logs[i], want))) << line;
    EXPECT_EQ(field(line, "step_count"), static_cast<long long>(logs[i]->step_count())) << line;
  }
  EXPECT_TRUE(has(state, "\"sync\": \"" + mode + "\"")) << state;
}

TEST_P(SideBySide, TwoRunsFollowOneTimelineInEachMode) {
  const std::vector<const replay::LogReader*> logs = {golden::lesson_run(kOffcenter), golden::lesson_run(kCircumcenter)};
  ASSERT_TRUE(logs[0] && logs[1]);
  std::string script;
  const char* modes[] = {"step", "vertices", "fraction"};
  for (const char* mode : modes)
    script += std::string("sync ") + mode + "\nseek step 20\nframes 1\nstate " + path(std::string(mode) + "_20.json") +
              "\nseek end\nframes 1\nstate " + path(std::string(mode) + "_end.json") + "\n";
  script += "quit\n";
  SIDE_OR_SKIP(r, logs, script);
  for (const char* mode : modes) {
    const std::string at20 = read_text(path(std::string(mode) + "_20.json"));
    expect_synced(at20, logs, mode);
    EXPECT_EQ(field(at20, "step"), 20) << at20;
    expect_synced(read_text(path(std::string(mode) + "_end.json")), logs, mode);
  }
  // Each run's caption is its description; statistics at the end are its own.
  const std::string end = read_text(path("step_end.json"));
  EXPECT_TRUE(has(run_line(end, 0), "\"caption\": \"offcenter, min angle 30\"")) << end;
  EXPECT_TRUE(has(run_line(end, 1), "\"caption\": \"circumcenter, min angle 30\"")) << end;
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string line = run_line(end, i);
    const auto at = line.find("\"min_angle\": ");
    ASSERT_NE(at, std::string::npos) << line;
    EXPECT_GE(std::atof(line.c_str() + at + 13), 30.0 - 1e-9) << "a finished run meets its bound: " << line;
    EXPECT_GT(field(line, "steiner"), 0) << line;
  }
  // Side by side: two canvases of one size, next to each other.
  const std::string l0 = run_line(end, 0), l1 = run_line(end, 1);
  EXPECT_EQ(field(l0, "width"), field(l1, "width"));
  EXPECT_GT(field(l1, "x"), field(l0, "x") + field(l0, "width") - 1) << l0 << "\n" << l1;
  EXPECT_EQ(field(l0, "y"), field(l1, "y"));
}

TEST_P(SideBySide, FourRunsInTwoRowsOfTwo) {
  const std::vector<const replay::LogReader*> logs = {golden::lesson_run(kOffcenter), golden::lesson_run(kCircumcenter),
                                                      golden::lesson_run(kCavity), golden::lesson_run(kLeppMidpoint)};
  for (const auto* log : logs) ASSERT_NE(log, nullptr);
  std::string script;
  for (const char* mode : {"step", "vertices", "fraction"})
    script += std::string("sync ") + mode + "\nseek step 12\nkey Right\nstate " + path(std::string(mode) + ".json") + "\n";
  script += "quit\n";
  SIDE_OR_SKIP(r, logs, script);
  for (const char* mode : {"step", "vertices", "fraction"}) expect_synced(read_text(path(std::string(mode) + ".json")), logs, mode);
  const std::string s = read_text(path("step.json"));
  EXPECT_EQ(field(s, "step"), 13) << "Right moved the timeline's run a step: " << s;
  const std::string r0 = run_line(s, 0), r1 = run_line(s, 1), r2 = run_line(s, 2), r3 = run_line(s, 3);
  EXPECT_EQ(field(r0, "y"), field(r1, "y"));
  EXPECT_EQ(field(r2, "y"), field(r3, "y"));
  EXPECT_GT(field(r2, "y"), field(r0, "y") + field(r0, "height") - 1);
  EXPECT_EQ(field(r0, "x"), field(r2, "x"));
  EXPECT_TRUE(has(r2, "\"caption\": \"offcenter, min angle 30, cavity\"")) << r2;
}

// Four runs side by side at rest, the overlay on: their frames allocate nothing (the side
// panel's statistics in columns, the steps per phase among them, the overlay's legends).
// On main they allocated 14 times a frame (the steps per phase's labels, made every frame).
TEST_P(SideBySide, IdleFramesAllocateNothing) {
  const std::vector<const replay::LogReader*> logs = {golden::lesson_run(kOffcenter), golden::lesson_run(kCircumcenter),
                                                      golden::lesson_run(kCavity), golden::lesson_run(kLeppMidpoint)};
  for (const auto* log : logs) ASSERT_NE(log, nullptr);
  const std::string frames = path("frames.txt");
  // A first frame lays the canvases out, so that `wait` then waits for their pictures.
  SIDE_OR_SKIP(r, logs, "frames 1\nseek step 30\ndifference on\nwait\nframes 8\nseek step 40\nwait\nframes 8\nquit\n",
               "--frame-log " + frames);
  const std::vector<unsigned long long> allocations = frame_allocations(frames);
  ASSERT_EQ(allocations.size(), 17u);
  // Frames 1 and 9 show the new moments (and ImGui sizes its buffers over the first
  // frames): the two after each are left to warm up, the other five of each are idle.
  for (std::size_t i = 4; i < 9; ++i) EXPECT_EQ(allocations[i], 0u) << "idle frame " << i;
  for (std::size_t i = 12; i < 17; ++i) EXPECT_EQ(allocations[i], 0u) << "idle frame " << i;
  if (MESHSTEP_VIEW_COUNTS_NEW) {
    EXPECT_GT(allocations[9], 0u) << "the frame after a move takes new moments";
  }
}

// Counts the pixels of the overlay's colour (Okabe-Ito's reddish purple, 204 121 167,
// within a few units: lines are antialiased) in a rectangle of the screenshot.
std::size_t overlay_pixels(const scene::Image& image, int x0, int y0, int x1, int y1) {
  std::size_t n = 0;
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) {
      const std::uint8_t* p = image.row(y) + 4 * x;
      n += std::abs(p[0] - 204) <= 6 && std::abs(p[1] - 121) <= 6 && std::abs(p[2] - 167) <= 6;
    }
  return n;
}

TEST_P(SideBySide, TheDifferenceOverlayMarksEachCanvas) {
  const std::vector<const replay::LogReader*> logs = {golden::lesson_run(kOffcenter), golden::lesson_run(kCircumcenter)};
  ASSERT_TRUE(logs[0] && logs[1]);
  // Step 45: the two refinements have gone different ways. Step 30: they still agree (the
  // same points so far), and the overlay has nothing to mark.
  SIDE_OR_SKIP(r, logs,
               "seek step 45\nscreenshot " + path("off.png") + "\nkey D\nstate " + path("on.json") + "\nscreenshot " +
                   path("on.png") + "\nseek step 30\nstate " + path("same.json") + "\ndifference off\nstate " +
                   path("off.json") + "\nquit\n");
  const std::string on = read_text(path("on.json")), same = read_text(path("same.json"));
  EXPECT_TRUE(has(on, "\"difference\": true")) << on;
  EXPECT_TRUE(has(read_text(path("off.json")), "\"difference\": false"));
  const scene::Image before = scene::read_png(path("off.png")), after = scene::read_png(path("on.png"));
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string key = "edges_not_in_run_" + std::to_string(i == 0 ? 2 : 1);
    const std::string line = run_line(on, i);
    const long long differ = field(line, key);
    EXPECT_GT(differ, 0) << "two algorithms' meshes differ at step 45: " << line;
    EXPECT_EQ(field(run_line(same, i), key), 0) << "and agree at step 30: " << run_line(same, i);
    const int x = static_cast<int>(field(line, "x")), y = static_cast<int>(field(line, "y"));
    const int w = static_cast<int>(field(line, "width")), h = static_cast<int>(field(line, "height"));
    EXPECT_EQ(overlay_pixels(before, x, y, x + w, y + h), 0u) << "no purple without the overlay, canvas " << i;
    // Each marked edge is tens of pixels long and 2.5 wide: far more than the legend's swatch.
    EXPECT_GT(overlay_pixels(after, x, y, x + w, y + h), 20u * static_cast<std::size_t>(differ))
        << "the overlay on canvas " << i;
  }
}

// The pixels of a rectangle of a picture that differ from another's by more than 5.
std::size_t changed_pixels(const scene::Image& a, const scene::Image& b, int x0, int y0, int x1, int y1) {
  std::size_t n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t *p = a.row(y) + 4 * x, *q = b.row(y) + 4 * x;
      n += std::abs(p[0] - q[0]) > 5 || std::abs(p[1] - q[1]) > 5 || std::abs(p[2] - q[2]) > 5;
    }
  return n;
}

// Linked cameras: a drag and a wheel over the second canvas move the first's picture too
// (one camera), and the first canvas's picture moved as much as the second's did.
TEST_P(SideBySide, APanOnOneCanvasMovesEveryCanvas) {
  const std::vector<const replay::LogReader*> logs = {golden::lesson_run(kOffcenter), golden::lesson_run(kCircumcenter)};
  ASSERT_TRUE(logs[0] && logs[1]);
  SIDE_OR_SKIP(r, logs,
               "seek step 30\nscreenshot " + path("a.png") + "\nstate " + path("a.json") +
                   "\nmouse 700 300\ndrag 60 30\nwheel 2\nstate " + path("b.json") + "\nscreenshot " + path("b.png") +
                   "\nquit\n");
  const std::string a = read_text(path("a.json")), b = read_text(path("b.json"));
  const auto number = [](const std::string& json, const std::string& key) {
    const auto at = json.find("\"" + key + "\": ");
    return at == std::string::npos ? NAN : std::atof(json.c_str() + at + key.size() + 4);
  };
  EXPECT_GT(number(b, "pixels_per_unit"), 1.3 * number(a, "pixels_per_unit")) << b;
  EXPECT_NE(number(b, "x"), number(a, "x")) << b;
  // At step 30 both runs have the same mesh: the same camera shows the same pictures, before
  // and after the move, on both canvases.
  const scene::Image before = scene::read_png(path("a.png")), after = scene::read_png(path("b.png"));
  const std::string l0 = run_line(a, 0), l1 = run_line(a, 1);
  const int x0 = static_cast<int>(field(l0, "x")), x1 = static_cast<int>(field(l1, "x"));
  const int y = static_cast<int>(field(l0, "y")) + 40, w = static_cast<int>(field(l0, "width")),
            h = static_cast<int>(field(l0, "height")) - 80;  // below the renderer's caption, above the legend
  EXPECT_GT(changed_pixels(before, after, x0, y, x0 + w, y + h), 5000u) << "the first canvas moved with the second";
  std::size_t differ = 0;
  for (int yy = y; yy < y + h; ++yy)
    for (int xx = 0; xx < w; ++xx) {
      const std::uint8_t *p = after.row(yy) + 4 * (x0 + xx), *q = after.row(yy) + 4 * (x1 + xx);
      differ += std::abs(p[0] - q[0]) > 5 || std::abs(p[1] - q[1]) > 5 || std::abs(p[2] - q[2]) > 5;
    }
  EXPECT_LT(differ, static_cast<std::size_t>(w) * static_cast<std::size_t>(h) / 50) << "the two canvases show one view";
}

// The side-by-side window with the overlay on, against tests/golden/viewer_side_by_side.png
// (5 per channel on at most 0.1% of the pixels, as the other viewer goldens). The logs are
// copied under fixed names: the side panel shows the leader's file name.
TEST_P(SideBySide, WindowWithTheOverlayMatchesItsGolden) {
  const replay::LogReader* off = golden::lesson_run(kOffcenter);
  const replay::LogReader* circ = golden::lesson_run(kCircumcenter);
  ASSERT_TRUE(off && circ);
  std::filesystem::copy_file(off->path(), dir_ / "offcenter.mslog");
  std::filesystem::copy_file(circ->path(), dir_ / "circumcenter.mslog");
  const replay::LogReader a(path("offcenter.mslog")), b(path("circumcenter.mslog"));
  SIDE_OR_SKIP(r, (std::vector<const replay::LogReader*>{&a, &b}),
               "seek step 45\ndifference on\nframes 2\nscreenshot " + path("shot.png") + "\nquit\n");
  const scene::Image actual = scene::read_png(path("shot.png"));
  ASSERT_EQ(actual.width, 1280);
  const std::filesystem::path golden = std::filesystem::path(MESHSTEP_GOLDEN_DIR) / "viewer_side_by_side.png";
  if (std::getenv("MESHSTEP_UPDATE_GOLDENS") && GetParam() == "egl") {
    scene::write_png(golden.string(), actual, 9);
    GTEST_SKIP() << "updated " << golden;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing: run with MESHSTEP_UPDATE_GOLDENS=1 and look at it";
  const scene::ImageDiff diff = scene::compare_images(scene::read_png(golden.string()), actual, 5);
  const std::size_t allowed = static_cast<std::size_t>(actual.width) * static_cast<std::size_t>(actual.height) / 1000;
  if (!diff.same_size || diff.differing_pixels > allowed) {
    std::filesystem::create_directories(MESHSTEP_GOLDEN_OUT);
    const std::string stem = std::string(MESHSTEP_GOLDEN_OUT) + "/viewer_side_by_side." + GetParam();
    scene::write_png(stem + ".actual.png", actual);
    if (diff.same_size) scene::write_png(stem + ".diff.png", diff.picture);
    ADD_FAILURE() << diff.differing_pixels << " pixels differ by more than 5 (allowed " << allowed << "); see " << stem
                  << ".actual.png and .diff.png";
  }
}

// "Compare with...": the open run's input run again with another refinement, live, then
// both side by side; the new run is the run `meshstep refine` records with those options
// (the same steps and events as the golden circumcenter log), and a refinement that cannot
// be run is said on the canvas, nothing else changing.
TEST_P(SideBySide, CompareWithRunsTheInputAgainAndShowsBoth) {
  const replay::LogReader* off = golden::lesson_run(kOffcenter);
  const replay::LogReader* circ = golden::lesson_run(kCircumcenter);
  ASSERT_TRUE(off && circ);
  SIDE_OR_SKIP(r, (std::vector<const replay::LogReader*>{off}),
               "frames 1\ncompare-with --algorithm nosuch\nframes 1\nstate " + path("refused.json") +
                   "\ncompare-with --algorithm circumcenter --min-angle 30\nframes 1\nseek end\nstate " +
                   path("both.json") + "\nquit\n");
  const std::string refused = read_text(path("refused.json"));
  EXPECT_TRUE(has(refused, "\"notice\": \"compare with: --algorithm: 'nosuch' is not one of")) << refused;
  EXPECT_TRUE(has(refused, "\"sync\": null")) << "still one run: " << refused;
  const std::string both = read_text(path("both.json"));
  const std::string first = run_line(both, 0), second = run_line(both, 1);
  EXPECT_TRUE(has(first, "\"path\": \"" + off->path() + "\"")) << first;
  EXPECT_TRUE(has(first, "\"caption\": \"offcenter, min angle 30\"")) << first;
  EXPECT_TRUE(has(second, "\"caption\": \"circumcenter, min angle 30\"")) << second;
  EXPECT_TRUE(has(second, "lesson.poly (compared)")) << second;
  EXPECT_EQ(field(second, "step_count"), static_cast<long long>(circ->step_count())) << second;
  EXPECT_EQ(field(second, "event_count"), static_cast<long long>(circ->event_count())) << second;
  EXPECT_EQ(field(second, "position"), static_cast<long long>(circ->event_count())) << second;
  EXPECT_EQ(field(first, "position"), static_cast<long long>(off->event_count())) << "the shorter run rests at its end";
}

INSTANTIATE_TEST_SUITE_P(Modes, SideBySide, ::testing::Values("egl", "osmesa", "window"),
                         [](const auto& info) { return info.param; });

// Bad input: more than four, or an input among logs, is a usage error; a file that is no
// log is refused, before any window.
TEST(SideBySideProgram, RefusesWhatItCannotShow) {
  const replay::LogReader* a = golden::lesson_run(kOffcenter);
  ASSERT_NE(a, nullptr);
  const std::string view = std::string(MESHSTEP_VIEW_BINARY) + " ";
  const std::string five = a->path() + " " + a->path() + " " + a->path() + " " + a->path() + " " + a->path();
  Result r = testing::run(view + five + " --offscreen");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r.output, "at most 4 runs side by side")) << r.output;
  r = testing::run(view + a->path() + " " + golden::asset("lesson.poly") + " --offscreen");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r.output, "runs side by side are replay logs")) << r.output;
  r = testing::run(view + a->path() + " " + golden::asset("lesson.poly") + ".missing --offscreen");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(has(r.output, "does not exist")) << r.output;
  // A file that is no log: its reader's words, and no window.
  const std::string junk = (std::filesystem::temp_directory_path() / ("junk_" + std::to_string(::getpid()) + ".mslog")).string();
  std::ofstream(junk) << "not a log\n";
  r = testing::run(view + a->path() + " " + junk + " --offscreen");
  std::filesystem::remove(junk);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(has(r.output, junk + ":")) << r.output;
}

}  // namespace
}  // namespace meshstep::viewer
