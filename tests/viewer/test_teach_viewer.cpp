// The viewer's tours and quiz, driven by scripts off screen: `--tour` opens at the first
// stop with its caption on the canvas, `tour next`/N/P move between stops whose steps are
// checked against the log's own step kinds, scrubbing away hides the caption; the quiz's
// score follows right and wrong answers made from the log's events read here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "meshstep/replay/event.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/teach/tour.hpp"
#include "program_support.hpp"

namespace meshstep::viewer::testing {
namespace {

namespace fs = std::filesystem;

class TeachViewer : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("meshstep_teach_viewer_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // The run the Ruppert tour records, recorded here too.
  std::string record_ruppert() {
    const std::string log = path("ruppert.mslog");
    const Result r = run(std::string(MESHSTEP_BINARY) + " refine " + MESHSTEP_ASSETS +
                         "/examples/lesson.poly --algorithm circumcenter --min-angle 30 --record " + log +
                         " --no-output -q");
    EXPECT_EQ(r.status, 0) << r.output;
    return log;
  }
  fs::path dir_;
};

// The "tour" or "quiz" field's line of a state file.
std::string line_of(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return "";
  return json.substr(at, json.find('\n', at) - at);
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

TEST_F(TeachViewer, ATourOpensAtItsFirstStopAndMovesFromStopToStop) {
  const std::string tour_path = std::string(MESHSTEP_ASSETS) + "/tours/ruppert.tour";
  const teach::Tour tour = teach::read_tour(tour_path);
  const replay::LogReader log(record_ruppert());
  std::ofstream(path("s.txt")) << "state " << path("1.json") << "\ntour next\nstate " << path("2.json")
                               << "\nkey N\nstate " << path("3.json") << "\nseek step 40\nstate " << path("4.json")
                               << "\nkey N\nstate " << path("5.json") << "\ntour stop 1\nkey P\nstate " << path("6.json")
                               << "\ntour stop 6\nscreenshot " << path("end.png") << "\nstate " << path("7.json") << "\n";
  const Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " --tour " + tour_path + " --window 1280x720 -q --script " +
                       path("s.txt") + " --offscreen --gl egl");
  if (r.status != 0 && has(r.output, "cannot open a window or draw")) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;

  // The steps the stops show, from the log's step kinds: the tour's first (a step number),
  // the carving, the first segment split after it.
  std::uint64_t carve = 0, split = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    if (!carve && log.step_kind(k) == replay::StepKind::carve) carve = k + 1;
    else if (carve && !split && log.step_kind(k) == replay::StepKind::split_segment) split = k + 1;
  }
  ASSERT_GT(carve, 0u);
  ASSERT_GT(split, carve);
  ASSERT_EQ(tour.stops[0].where, teach::TourStop::Where::step);
  const auto first = static_cast<long long>(tour.stops[0].step), last = static_cast<long long>(log.step_count());
  ASSERT_LT(first, 40);
  const auto step_of = [](const std::string& json) { return field(json, "step"); };
  const std::string s1 = read_text(path("1.json")), s2 = read_text(path("2.json")), s3 = read_text(path("3.json"));
  EXPECT_EQ(step_of(s1), first);
  EXPECT_TRUE(has(line_of(s1, "tour"), "\"stop\": 1, \"stops\": 6, \"at_stop\": true")) << line_of(s1, "tour");
  EXPECT_TRUE(has(line_of(s1, "tour"), "\"narration\": " + quoted(tour.stops[0].caption))) << line_of(s1, "tour");
  EXPECT_EQ(step_of(s2), static_cast<long long>(carve));
  EXPECT_TRUE(has(line_of(s2, "tour"), "\"stop\": 2,")) << line_of(s2, "tour");
  EXPECT_EQ(step_of(s3), static_cast<long long>(split));
  EXPECT_TRUE(has(line_of(s3, "tour"), "\"narration\": " + quoted(tour.stops[2].caption)));
  // Scrubbed away (step 40, between stops 5 and 6): no caption; N goes to the first stop
  // after the cursor, the end.
  const std::string s4 = read_text(path("4.json")), s5 = read_text(path("5.json"));
  EXPECT_TRUE(has(line_of(s4, "tour"), "\"at_stop\": false")) << line_of(s4, "tour");
  EXPECT_TRUE(has(line_of(s4, "tour"), "\"narration\": \"\"")) << line_of(s4, "tour");
  EXPECT_EQ(step_of(s5), last);
  EXPECT_TRUE(has(line_of(s5, "tour"), "\"stop\": 6, \"stops\": 6, \"at_stop\": true")) << line_of(s5, "tour");
  // P at the first stop: nothing before it (the canvas says so).
  const std::string s6 = read_text(path("6.json"));
  EXPECT_EQ(step_of(s6), first);
  EXPECT_TRUE(has(s6, "tour: this is the first stop")) << line_of(s6, "notice");
  const std::string s7 = read_text(path("7.json"));
  EXPECT_EQ(step_of(s7), last);
  EXPECT_TRUE(fs::file_size(path("end.png")) > 10000);
}

TEST_F(TeachViewer, ABadTourIsRefusedWithItsLineBeforeAnyWindow) {
  std::ofstream(path("bad.tour")) << "input " << MESHSTEP_ASSETS << "/examples/lesson.poly\nrun triangulate\n"
                                  << "stop next lepp\ncaption A Lepp path.\n";
  const Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " --tour " + path("bad.tour") + " --offscreen -q");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(has(r.output, path("bad.tour") + ":3: stop next lepp: no Lepp path after step 0")) << r.output;
  const Result both = run(std::string(MESHSTEP_VIEW_BINARY) + " " + path("bad.tour") + " --tour " + path("bad.tour") +
                          " --offscreen -q");
  EXPECT_EQ(both.status, 2) << both.output;
}

// The first refinement step's selected point, and the first Delaunay flip of the first step
// that has one, with a corner of the first triangle that is neither of the edge's ends.
struct Answers {
  std::uint64_t point_step = 0, flip_step = 0;
  Point point, flip_mid, elsewhere;
};

Answers answers_from(const replay::LogReader& log) {
  Answers a;
  const auto& v = log.vertices();
  std::array<std::uint32_t, 3> first{kNone, kNone, kNone};
  for (std::uint64_t e = 0; e < log.event_count() && !(a.point_step && a.flip_step); ++e) {
    const replay::Event ev = log.event(e);
    const std::uint64_t k = log.step_of_event(e) + 1;
    if (ev.type == replay::EventType::init) first = {ev.ids[0], ev.ids[1], ev.ids[2]};
    if (!a.point_step && ev.type == replay::EventType::point_selected) {
      a.point_step = k;
      a.point = ev.point;
    }
    if (!a.flip_step && ev.type == replay::EventType::flip && ev.code == 0) {
      a.flip_step = k;
      const Point p = v[ev.ids[0]].point, q = v[ev.ids[1]].point;
      a.flip_mid = {(p.x + q.x) / 2, (p.y + q.y) / 2};
      // A corner of the first triangle (in the mesh from step 1 on) that is not an end.
      for (const std::uint32_t c : first)
        if (c != ev.ids[0] && c != ev.ids[1] && c < v.size()) {
          a.elsewhere = v[c].point;
          break;
        }
    }
  }
  return a;
}

TEST_F(TeachViewer, TheQuizScoresRightAndWrongAnswers) {
  const std::string log_path = record_ruppert();
  const replay::LogReader log(log_path);
  const Answers a = answers_from(log);
  ASSERT_GT(a.point_step, 0u);
  ASSERT_GT(a.flip_step, 0u);
  const auto xy = [](Point p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.17g %.17g", p.x, p.y);
    return std::string(buf);
  };
  const std::string script = "seek start\nquiz on point\nstate " + path("q1.json") + "\nquiz answer " + xy(a.point) + "\nstate " +
                             path("q2.json") + "\nquiz next\nquiz answer 1000 1000\nstate " + path("q3.json") +
                             "\nquiz save " + path("summary.json") + "\nquiz off\nseek start\nquiz on flip\nstate " +
                             path("f1.json") + "\nquiz answer " + xy(a.elsewhere) + "\nstate " + path("f2.json") +
                             "\nseek start\nquiz on flip\nquiz answer " + xy(a.flip_mid) + "\nstate " + path("f3.json") + "\n";
  const Result r = view_log(MESHSTEP_VIEW_BINARY, log_path, dir_, "egl", "1280x720", script);
  if (r.status == 77) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string q1 = line_of(read_text(path("q1.json")), "quiz");
  EXPECT_TRUE(has(q1, "\"question\": \"point\", \"step\": " + std::to_string(a.point_step) + ", \"answered\": false"))
      << q1;
  // Asked at the moment before the step, with the last step's overlay hidden.
  EXPECT_EQ(field(read_text(path("q1.json")), "step"), static_cast<long long>(a.point_step - 1));
  const std::string q2 = line_of(read_text(path("q2.json")), "quiz");
  EXPECT_TRUE(has(q2, "\"answered\": true, \"asked\": 1, \"right\": 1, \"last\": {\"right\": true, \"distance\": 0}")) << q2;
  EXPECT_EQ(field(read_text(path("q2.json")), "step"), static_cast<long long>(a.point_step));
  const std::string q3 = line_of(read_text(path("q3.json")), "quiz");
  EXPECT_TRUE(has(q3, "\"asked\": 2, \"right\": 1, \"last\": {\"right\": false")) << q3;
  const std::string summary = read_text(path("summary.json"));
  EXPECT_TRUE(has(summary, "\"asked\": 2,\n  \"right\": 1,")) << summary;
  EXPECT_TRUE(has(summary, "\"step\": " + std::to_string(a.point_step) + ", \"question\": \"point\"")) << summary;

  const std::string f1 = line_of(read_text(path("f1.json")), "quiz");
  EXPECT_TRUE(has(f1, "\"question\": \"flip\", \"step\": " + std::to_string(a.flip_step))) << f1;
  // Wrong: a click on a vertex that is neither end picks an edge of that vertex.
  const std::string f2 = line_of(read_text(path("f2.json")), "quiz");
  EXPECT_TRUE(has(f2, "\"asked\": 1, \"right\": 0, \"last\": {\"right\": false")) << f2;
  // A new quiz starts a new score; the flipped edge's midpoint is right.
  const std::string f3 = line_of(read_text(path("f3.json")), "quiz");
  EXPECT_TRUE(has(f3, "\"question\": \"flip\", \"step\": " + std::to_string(a.flip_step))) << f3;
  EXPECT_TRUE(has(f3, "\"asked\": 1, \"right\": 1")) << f3;
}

// Every shipped tour plays in the viewer, off screen on EGL and OSMesa and in an Xvfb window:
// each stop, gone to by number, is at its stop with its own caption on the canvas.
class ShippedTourInViewer : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {
 protected:
  void SetUp() override {
    const auto& [tour, mode] = GetParam();
    dir_ = fs::temp_directory_path() / ("meshstep_tour_viewer_" + std::to_string(::getpid()) + "_" + tour + "_" + mode);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_P(ShippedTourInViewer, EveryStopShowsItsCaption) {
  const auto& [name, mode] = GetParam();
  const std::string tour_path = std::string(MESHSTEP_ASSETS) + "/tours/" + name + ".tour";
  const teach::Tour tour = teach::read_tour(tour_path);
  ASSERT_GE(tour.stops.size(), 3u);
  std::string script;
  for (std::size_t k = 1; k <= tour.stops.size(); ++k)
    script += "tour stop " + std::to_string(k) + "\nstate " + path(std::to_string(k) + ".json") + "\n";
  script += "screenshot " + path("last.png") + "\nquit\n";  // a window stays open without quit
  const Result r = view_log(MESHSTEP_VIEW_BINARY, "", dir_, mode, "1280x720", script, "--tour " + tour_path);
  if (r.status == 77) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  for (std::size_t k = 1; k <= tour.stops.size(); ++k) {
    const std::string state = read_text(path(std::to_string(k) + ".json"));
    const std::string tour_line = line_of(state, "tour");
    EXPECT_TRUE(has(tour_line, "\"stop\": " + std::to_string(k) + ", \"stops\": " + std::to_string(tour.stops.size()) +
                                   ", \"at_stop\": true"))
        << tour_line;
    EXPECT_TRUE(has(tour_line, "\"narration\": " + quoted(tour.stops[k - 1].caption))) << tour_line;
    // No tour asks for the Voronoi diagram: its stops show what `export --tour` draws.
    EXPECT_FALSE(has(line_of(state, "layers"), "voronoi")) << line_of(state, "layers");
  }
  EXPECT_GT(fs::file_size(path("last.png")), 10000u);
}

INSTANTIATE_TEST_SUITE_P(Shipped, ShippedTourInViewer,
                         ::testing::Combine(::testing::Values("ruppert", "offcenter", "lepp-centroid"),
                                            ::testing::Values("egl", "osmesa", "window")),
                         [](const auto& info) {
                           std::string tour = std::get<0>(info.param);
                           std::erase(tour, '-');
                           // The mode first: CI's sanitizer pass leaves out names with "/window".
                           return std::get<1>(info.param) + "_" + tour;
                         });

}  // namespace
}  // namespace meshstep::viewer::testing
