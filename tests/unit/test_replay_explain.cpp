// What a recorded run says about its steps, for the pictures that explain them: every
// point location's walk (the list of a locate event) and the bounds a refinement step's
// bad triangle missed (its criterion_test events). Checked against the geometry the log
// itself holds (LogReader::vertices), as a viewer would read it; also the command line's
// dumps of both, and that a version-2 log (locate events without their walk) still opens.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/geometry/predicates.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/mesh/tds.hpp"
#include "meshstep/refine/quality.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/replay/describe.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/recorder.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/verify.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using replay::Criterion;
using replay::Event;
using replay::EventType;
using testing::TempDir;

using Face = std::array<VertexId, 3>;  // counterclockwise

std::string plate() { return std::string(MESHSTEP_ASSETS) + "/examples/plate.poly"; }

// Records a refinement of `input` with `options` into `path`, the header's parameters
// naming the bounds as `meshstep refine --record` does.
void record_refinement(const Pslg& input, RefineOptions options, const std::string& path,
                       const replay::LogWriterOptions& writer_options = {}) {
  replay::LogHeader header;
  header.algorithm = options.algorithm;
  const RefineCriteria& c = options.criteria;
  header.parameters = "min_angle=" + std::to_string(c.min_angle_deg) + " max_angle=" + std::to_string(c.max_angle_deg) +
                      " max_aspect=" + std::to_string(c.max_aspect) + " max_area=" + std::to_string(c.max_area);
  replay::LogWriter writer(path, header, writer_options);
  options.triangulate.record = &writer;
  RefineReport report;
  refine(input, options, &report);
  writer.finish();
  ASSERT_GT(report.triangles_split, 0u);
}

RefineOptions at_angle(double degrees) {
  RefineOptions o;
  o.criteria.min_angle_deg = degrees;
  return o;
}

std::vector<Face> faces_of(std::span<const std::uint32_t> list) {
  std::vector<Face> faces;
  for (std::size_t i = 0; i + 3 <= list.size(); i += 3) faces.push_back({list[i], list[i + 1], list[i + 2]});
  return faces;
}

// Do f and g share an edge, as two faces of a triangulation do: u->v in one, v->u in the other?
bool share_an_edge(const Face& f, const Face& g) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (f[i] == g[(j + 1) % 3] && f[(i + 1) % 3] == g[j]) return true;
  return false;
}

// Is p in face f: inside it or on its boundary, or strictly inside? A ghost face (u, v, inf)
// stands for the outside of its hull edge: the half-plane left of u->v.
bool contains(const std::vector<replay::VertexInfo>& vertices, Face f, const Point& p, bool strictly) {
  while (f[0] == kInfiniteVertex || f[1] == kInfiniteVertex) std::rotate(f.begin(), f.begin() + 1, f.end());
  const auto left_of = [&](VertexId u, VertexId v) {
    const double o = orient2d(vertices[u].point, vertices[v].point, p);
    return strictly ? o > 0.0 : o >= 0.0;
  };
  if (f[2] == kInfiniteVertex) return left_of(f[0], f[1]);
  return left_of(f[0], f[1]) && left_of(f[1], f[2]) && left_of(f[2], f[0]);
}

// One locate event's walk: as long as the walk (or its last kMaxFaces), a chain of faces
// each sharing an edge with the one before, ending in a face that holds the point.
void check_walk(const replay::LogReader& log, const Event& e, std::uint64_t at) {
  SCOPED_TRACE("event " + std::to_string(at) + ": " + replay::describe(e));
  const std::uint32_t visited = e.ids[1];
  ASSERT_GE(visited, 1u);
  ASSERT_EQ(e.list.size(), 3 * std::min(visited, replay::WalkTrace::kMaxFaces));
  const std::vector<Face> walk = faces_of(e.list);
  for (std::size_t i = 1; i < walk.size(); ++i) ASSERT_TRUE(share_an_edge(walk[i - 1], walk[i])) << "face " << i;
  const Point& p = log.vertices().at(e.ids[0]).point;
  const bool in_face = e.code == static_cast<std::uint8_t>(replay::LocateResult::in_face);
  EXPECT_TRUE(contains(log.vertices(), walk.back(), p, in_face));
}

// The parameter `key` of the log's header, as a number.
double bound(const replay::LogReader& log, const std::string& key) {
  const std::string value = replay::header_parameter(log.header(), key);
  EXPECT_FALSE(value.empty()) << key << " is not in the header";
  return std::stod(value);
}

// The events of step k.
std::vector<Event> step_events(const replay::LogReader& log, std::uint64_t k) {
  std::vector<Event> events;
  for (std::uint64_t e = log.step_start(k); e < log.step_start(k + 1); ++e) events.push_back(log.event(e));
  return events;
}

bool is_step(const Event& e, replay::StepKind kind) {
  return e.type == EventType::step_begin && e.code == static_cast<std::uint8_t>(kind);
}

class ExplainPlate : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir("meshstep_explain_");
    record_refinement(io::read_poly(plate()), at_angle(30.0), dir_->file("plate.mslog"));
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::string log_path() { return dir_->file("plate.mslog"); }
  static TempDir* dir_;
};
TempDir* ExplainPlate::dir_ = nullptr;

TEST_F(ExplainPlate, EveryLocateCarriesItsWalk) {
  const replay::LogReader log(log_path());
  ASSERT_GE(log.format_version(), 3u);  // the walk came in version 3
  std::size_t walks = 0, longer_than_one = 0;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const Event ev = log.event(e);
    if (ev.type != EventType::locate) continue;
    check_walk(log, ev, e);
    ++walks;
    longer_than_one += ev.ids[1] > 1;
  }
  EXPECT_EQ(walks, log.counts_by_type()[static_cast<std::size_t>(EventType::locate)]);
  EXPECT_GT(longer_than_one, 0u) << "no walk went beyond its first face: the chain is not tested";
}

// The walk's last face is the record of the face slot the event names, at that moment.
TEST_F(ExplainPlate, TheWalkEndsInTheFaceFound) {
  const replay::LogReader log(log_path());
  replay::Replay cursor(log);
  std::size_t checked = 0;
  while (cursor.next_event()) {
    const Event e = *cursor.last_event();
    if (e.type != EventType::locate) continue;
    const std::vector<Face> walk = faces_of(e.list);
    ASSERT_FALSE(walk.empty());
    ASSERT_LT(e.ids[2], cursor.slots().size());
    EXPECT_EQ(cursor.slots()[e.ids[2]].v, walk.back()) << "event " << cursor.position() - 1;
    ++checked;
  }
  EXPECT_GT(checked, 0u);
}

// Every refine step opens with the bounds its bad triangle missed, before the point chosen
// for it: here the smallest angle, measured as the log's own coordinates give it.
TEST_F(ExplainPlate, RefineStepsSayWhichBoundTheirTriangleMissed) {
  const replay::LogReader log(log_path());
  const double min_angle = bound(log, "min_angle");
  ASSERT_EQ(min_angle, 30.0);
  std::size_t refine_steps = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    const std::vector<Event> events = step_events(log, k);
    if (!is_step(events.front(), replay::StepKind::refine)) continue;
    ++refine_steps;
    SCOPED_TRACE("step " + std::to_string(k) + " (event " + std::to_string(log.step_start(k)) + ")");
    const auto selected = std::find_if(events.begin(), events.end(),
                                       [](const Event& e) { return e.type == EventType::point_selected; });
    ASSERT_NE(selected, events.end());
    // Right after step_begin, up to point_selected: criterion tests and nothing else.
    ASSERT_GT(selected - events.begin(), 1) << "no criterion_test before point_selected";
    for (auto e = events.begin() + 1; e != selected; ++e) {
      ASSERT_EQ(e->type, EventType::criterion_test) << replay::describe(*e);
      ASSERT_EQ(e->code, static_cast<std::uint8_t>(Criterion::min_angle)) << "only an angle bound is set";
      // The triangle the point is for.
      EXPECT_TRUE(std::equal(e->ids.begin(), e->ids.begin() + 3, selected->ids.begin()));
      const auto& v = log.vertices();
      const quality::Shape s =
          quality::shape(v.at(e->ids[0]).point, v.at(e->ids[1]).point, v.at(e->ids[2]).point);
      EXPECT_DOUBLE_EQ(e->value, s.min_angle_deg());
      EXPECT_LT(e->value, min_angle);
    }
  }
  EXPECT_GT(refine_steps, 0u);
  EXPECT_EQ(refine_steps, log.counts_by_type()[static_cast<std::size_t>(EventType::point_selected)]);
}

TEST_F(ExplainPlate, LogVerifies) {
  const replay::LogReader log(log_path());
  ASSERT_TRUE(log.complete());
  const replay::VerifyReport report = replay::verify(log);
  EXPECT_TRUE(report.ok) << report.problem;
}

// With several bounds set, each one a triangle misses is its own test, with its own
// measure: angles in degrees, the aspect ratio, the area in the input's units.
TEST(ExplainCriteria, EachMissedBoundIsRecordedWithItsMeasure) {
  TempDir dir("meshstep_explain_");
  const std::string path = dir.file("several.mslog");
  RefineOptions o = at_angle(25.0);
  o.criteria.max_angle_deg = 120.0;
  o.criteria.max_aspect = 2.5;
  o.criteria.max_area = 0.05;
  record_refinement(io::read_poly(plate()), o, path);
  const replay::LogReader log(path);
  std::array<std::size_t, static_cast<std::size_t>(Criterion::count_)> seen{};
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const Event ev = log.event(e);
    if (ev.type != EventType::criterion_test) continue;
    ASSERT_FALSE(ev.code & replay::kCriterionPassed) << "only failures are recorded";
    const auto criterion = static_cast<Criterion>(ev.code);
    const auto& v = log.vertices();
    const Point &a = v.at(ev.ids[0]).point, &b = v.at(ev.ids[1]).point, &c = v.at(ev.ids[2]).point;
    const quality::Shape s = quality::shape(a, b, c);
    SCOPED_TRACE(replay::describe(ev));
    switch (criterion) {
      case Criterion::min_angle:
        EXPECT_DOUBLE_EQ(ev.value, s.min_angle_deg());
        EXPECT_LT(ev.value, bound(log, "min_angle"));
        break;
      case Criterion::max_angle:
        EXPECT_DOUBLE_EQ(ev.value, s.max_angle_deg());
        EXPECT_GT(ev.value, bound(log, "max_angle"));
        break;
      case Criterion::max_aspect:
        EXPECT_DOUBLE_EQ(ev.value, s.aspect());
        EXPECT_GT(ev.value, bound(log, "max_aspect"));
        break;
      case Criterion::max_area:
        EXPECT_DOUBLE_EQ(ev.value, s.area);
        EXPECT_GT(ev.value, bound(log, "max_area"));
        break;
      default: ADD_FAILURE() << "a bound that was not set: " << replay::name(criterion);
    }
    ++seen[static_cast<std::size_t>(criterion)];
  }
  for (const Criterion c : {Criterion::min_angle, Criterion::max_angle, Criterion::max_aspect, Criterion::max_area})
    EXPECT_GT(seen[static_cast<std::size_t>(c)], 0u) << replay::name(c) << " never failed: not tested";
}

// Lepp bisection: each bisect step names the area of the target it works towards, before
// its path (the triangle bisected is the path's terminal one, not necessarily the target).
TEST(ExplainCriteria, BisectStepsRecordTheTargetsArea) {
  TempDir dir("meshstep_explain_");
  const std::string path = dir.file("bisect.mslog");
  RefineOptions o;
  o.algorithm = "lepp-bisection";
  o.insertion = RefineInsertion::bisection;
  o.criteria.max_area = 0.1;
  record_refinement(io::read_poly(plate()), o, path);
  const replay::LogReader log(path);
  std::size_t bisections = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    const std::vector<Event> events = step_events(log, k);
    if (!is_step(events.front(), replay::StepKind::bisect)) continue;
    ++bisections;
    ASSERT_GE(events.size(), 3u);
    const Event& test = events[1];
    ASSERT_EQ(test.type, EventType::criterion_test) << "step " << k;
    EXPECT_EQ(test.code, static_cast<std::uint8_t>(Criterion::max_area));
    const auto& v = log.vertices();
    EXPECT_DOUBLE_EQ(test.value,
                     quality::shape(v.at(test.ids[0]).point, v.at(test.ids[1]).point, v.at(test.ids[2]).point).area);
    EXPECT_GT(test.value, 0.1);
    EXPECT_EQ(events[2].type, EventType::lepp_path);
  }
  EXPECT_GT(bisections, 0u);
}

TEST(ExplainCriteria, CodesNameTheCriterionAndTheOutcome) {
  EXPECT_EQ(replay::code_name(EventType::criterion_test, static_cast<std::uint8_t>(Criterion::min_angle)),
            "min_angle failed");
  EXPECT_EQ(replay::code_name(EventType::criterion_test,
                              static_cast<std::uint8_t>(Criterion::size) | replay::kCriterionPassed),
            "size passed");
  EXPECT_EQ(replay::code_name(EventType::criterion_test, 0x7F), "127 failed");
  EXPECT_STREQ(replay::name(Criterion::local_max_area), "local_max_area");
}

// A walk longer than the cap keeps its last kMaxFaces faces: points along a strip, inserted
// from its middle outwards, alternately on either side, so that every walk starts at one end
// of the strip made so far and crosses it to the other.
TEST(ExplainWalk, LongWalksKeepTheirLastFaces) {
  constexpr int kHalf = 400;
  std::vector<Point> points;
  for (int i = 0; i < kHalf; ++i) {
    for (const int x : {kHalf - 1 - i, kHalf + i}) points.push_back({static_cast<double>(x), (x * 7919 % 13) / 13.0});
  }
  TempDir dir("meshstep_explain_");
  const std::string path = dir.file("strip.mslog");
  {
    replay::LogWriter writer(path, replay::LogHeader{});
    Triangulation<Tds, replay::Recorder> tri(points, Insertion::flip, replay::Recorder(writer));
    tri.insert_all();
    tri.recorder().run_end(tri.mesh());
    writer.finish();
  }
  const replay::LogReader log(path);
  std::size_t capped = 0;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const Event ev = log.event(e);
    if (ev.type != EventType::locate) continue;
    check_walk(log, ev, e);
    capped += ev.ids[1] > replay::WalkTrace::kMaxFaces;
  }
  EXPECT_GT(capped, 0u) << "no walk was longer than the cap";
  const replay::VerifyReport report = replay::verify(log);
  EXPECT_TRUE(report.ok) << report.problem;
}

// A log of format version 2 (written as meshstep wrote them before locate events carried
// their walk) opens, verifies, and holds the same events but for those lists.
TEST(ExplainFormat, VersionTwoLogsStillOpen) {
  TempDir dir("meshstep_explain_");
  const Pslg input = io::read_poly(plate());
  replay::LogWriterOptions v2;
  v2.format_version = 2;
  record_refinement(input, at_angle(30.0), dir.file("v2.mslog"), v2);
  replay::LogWriterOptions v3;  // the walks' own cost: format 5's compact events hide it
  v3.format_version = 3;
  record_refinement(input, at_angle(30.0), dir.file("v3.mslog"), v3);
  const replay::LogReader old_log(dir.file("v2.mslog")), log(dir.file("v3.mslog"));
  EXPECT_EQ(old_log.format_version(), 2u);
  ASSERT_TRUE(old_log.complete());
  const replay::VerifyReport report = replay::verify(old_log);
  EXPECT_TRUE(report.ok) << report.problem;
  ASSERT_EQ(old_log.event_count(), log.event_count());
  EXPECT_LT(old_log.file_size(), log.file_size());
  std::size_t locates = 0;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    Event old_event = old_log.event(e);
    Event event = log.event(e);
    if (event.type == EventType::locate) {
      ++locates;
      EXPECT_TRUE(old_event.list.empty());
      EXPECT_FALSE(event.list.empty());
      event.list = {};
    }
    ASSERT_EQ(replay::describe(old_event), replay::describe(event)) << "event " << e;
  }
  EXPECT_GT(locates, 0u);
}

// A log of format version 4 (before compact event heads, flips and split_faces) opens,
// verifies, and holds the very same events as a version-5 log, which is smaller. The plate's
// refinement has constrained edges, so the compact forms' fallbacks (constraint bits, a
// split_face with its bits whole) are read back as well as their common cases.
TEST(ExplainFormat, VersionFourLogsStillOpen) {
  TempDir dir("meshstep_explain_");
  const Pslg input = io::read_poly(plate());
  replay::LogWriterOptions v4;
  v4.format_version = 4;
  record_refinement(input, at_angle(30.0), dir.file("v4.mslog"), v4);
  record_refinement(input, at_angle(30.0), dir.file("v5.mslog"));
  const replay::LogReader old_log(dir.file("v4.mslog")), log(dir.file("v5.mslog"));
  EXPECT_EQ(old_log.format_version(), 4u);
  EXPECT_EQ(log.format_version(), 6u);
  for (const replay::LogReader* l : {&old_log, &log}) {
    ASSERT_TRUE(l->complete());
    const replay::VerifyReport report = replay::verify(*l);
    EXPECT_TRUE(report.ok) << report.problem;
  }
  EXPECT_LT(log.file_size(), old_log.file_size());
  ASSERT_EQ(old_log.event_count(), log.event_count());
  std::size_t constrained_flips = 0;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const Event event = log.event(e);
    ASSERT_EQ(replay::describe(old_log.event(e)), replay::describe(event)) << "event " << e;
    if (event.type == EventType::flip)
      for (const replay::SlotWrite& w : event.writes) constrained_flips += w.before.constrained != 0;
  }
  EXPECT_GT(constrained_flips, 0u) << "no flip touched a constrained edge: the fallback went untested";
}

// What format 5 is for: a Delaunay triangulation's log, flips and split_faces for the most
// part, is at least a fifth smaller than in format 4 (19.0 against 15.0 bytes an event at 1e6
// points, keyframes included), and replays the same.
TEST(ExplainFormat, VersionFiveIsSmaller) {
  TempDir dir("meshstep_explain_");
  std::mt19937_64 engine(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Pslg input;
  for (int i = 0; i < 20000; ++i) input.points.push_back({unit(engine), unit(engine)});
  const auto record = [&](std::uint32_t version, const std::string& path) {
    replay::LogWriterOptions o;
    o.format_version = version;
    replay::LogWriter writer(path, replay::LogHeader{}, o);
    TriangulateOptions options;
    options.record = &writer;
    triangulate(Pslg(input), options);
    writer.finish();
  };
  record(4, dir.file("v4.mslog"));
  record(5, dir.file("v5.mslog"));
  const replay::LogReader old_log(dir.file("v4.mslog")), log(dir.file("v5.mslog"));
  const replay::VerifyReport report = replay::verify(log);
  EXPECT_TRUE(report.ok) << report.problem;
  ASSERT_EQ(old_log.event_count(), log.event_count());
  EXPECT_LT(static_cast<double>(log.file_size()), 0.8 * static_cast<double>(old_log.file_size()));
  for (std::uint64_t e = 0; e < log.event_count(); e += 7)
    ASSERT_EQ(replay::describe(old_log.event(e)), replay::describe(log.event(e))) << "event " << e;
}

// A log of format version 3 (before terrains' elevation events: its end block counts one
// event type fewer) opens, verifies, and holds the very same events as a version-4 log.
TEST(ExplainFormat, VersionThreeLogsStillOpen) {
  TempDir dir("meshstep_explain_");
  const Pslg input = io::read_poly(plate());
  replay::LogWriterOptions v3;
  v3.format_version = 3;
  record_refinement(input, at_angle(30.0), dir.file("v3.mslog"), v3);
  replay::LogWriterOptions v4;
  v4.format_version = 4;
  record_refinement(input, at_angle(30.0), dir.file("v4.mslog"), v4);
  const replay::LogReader old_log(dir.file("v3.mslog")), log(dir.file("v4.mslog"));
  EXPECT_EQ(old_log.format_version(), 3u);
  EXPECT_EQ(log.format_version(), 4u);
  ASSERT_TRUE(old_log.complete());
  const replay::VerifyReport report = replay::verify(old_log);
  EXPECT_TRUE(report.ok) << report.problem;
  EXPECT_FALSE(old_log.has_elevation());
  ASSERT_EQ(old_log.event_count(), log.event_count());
  for (std::uint64_t e = 0; e < log.event_count(); ++e)
    ASSERT_EQ(replay::describe(old_log.event(e)), replay::describe(log.event(e))) << "event " << e;
}

// Format 6 changed only the header (a recipe's operations): a version-5 log of the same run
// holds the same bytes of events and reads the same; a version-5 writer refuses operations,
// which a version-5 reader would take for one run's phases.
TEST(ExplainFormat, VersionFiveLogsStillOpen) {
  TempDir dir("meshstep_explain_");
  const Pslg input = io::read_poly(plate());
  replay::LogWriterOptions v5;
  v5.format_version = 5;
  record_refinement(input, at_angle(30.0), dir.file("v5.mslog"), v5);
  record_refinement(input, at_angle(30.0), dir.file("v6.mslog"));
  const replay::LogReader old_log(dir.file("v5.mslog")), log(dir.file("v6.mslog"));
  EXPECT_EQ(old_log.format_version(), 5u);
  EXPECT_EQ(log.format_version(), 6u);
  const replay::VerifyReport report = replay::verify(old_log);
  EXPECT_TRUE(report.ok) << report.problem;
  EXPECT_EQ(old_log.header().parameters, log.header().parameters);
  ASSERT_EQ(old_log.event_count(), log.event_count());
  for (std::uint64_t e = 0; e < log.event_count(); ++e)
    ASSERT_EQ(replay::describe(old_log.event(e)), replay::describe(log.event(e))) << "event " << e;

  replay::LogHeader chain;
  chain.operations = "refine --algorithm lepp-centroid --min-angle 25\nrefine --max-area 0.1";
  EXPECT_THROW(replay::LogWriter(dir.file("chain5.mslog"), chain, v5), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir.file("chain5.mslog")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("chain5.mslog.partial")));
  // (Version 6 logs of chains are read in test_run_recipe_cli.cpp.)
}

TEST(ExplainFormat, OnlyKnownVersionsAreWritten) {
  TempDir dir("meshstep_explain_");
  for (const std::uint32_t version : {1u, 7u}) {
    replay::LogWriterOptions o;
    o.format_version = version;
    EXPECT_THROW(replay::LogWriter(dir.file("x.mslog"), replay::LogHeader{}, o), std::invalid_argument) << version;
  }
}

// The command line: `log dump` shows the walk and the criterion tests, as text and as
// JSON, and `log verify` passes.
TEST(ExplainCli, DumpShowsWalksAndCriterionTests) {
  TempDir dir("meshstep_explain_");
  const std::string log = dir.file("plate.mslog");
  const auto run = [&](const std::string& args) { return testing::run_meshstep(args, dir.path()); };
  testing::CommandResult r = run("refine " + plate() + " --min-angle 30 --no-output -q --record " + log);
  ASSERT_EQ(r.status, 0) << r.err;
  r = run("log verify -q " + log);
  EXPECT_EQ(r.status, 0) << r.out << r.err;

  r = run("log dump " + log);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("criterion_test min_angle failed a="), std::string::npos);
  const std::size_t locate = r.out.find(" locate in_face vertex=");
  ASSERT_NE(locate, std::string::npos);
  const std::string line = r.out.substr(locate, r.out.find('\n', locate) - locate);
  EXPECT_NE(line.find(" list=["), std::string::npos) << line;

  r = run("log dump --jsonl " + log);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"type\":\"criterion_test\",\"code\":\"min_angle failed\""), std::string::npos);
  const std::size_t json_locate = r.out.find("\"type\":\"locate\"");
  ASSERT_NE(json_locate, std::string::npos);
  const std::string object = r.out.substr(json_locate, r.out.find('\n', json_locate) - json_locate);
  EXPECT_NE(object.find("\"list\":["), std::string::npos) << object;
  EXPECT_EQ(object.find("\"list\":[]"), std::string::npos) << object;
}

}  // namespace
}  // namespace meshstep
