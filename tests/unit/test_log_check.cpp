// `meshstep log check` and replay::check_invariants: recorded runs hold their invariants at
// every step boundary, and a log whose mesh stops being Delaunay at a known step is
// reported at exactly that step, whether every boundary is checked or bisection has to
// find it between coarser samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshstep/check/mesh_check.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/geometry/predicates.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/mesh/tds.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/replay/invariants.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/recorder.hpp"
#include "meshstep/replay/replay.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using replay::Invariant;
using testing::CommandResult;
using testing::TempDir;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::vector<Point> uniform(std::size_t n, std::uint64_t seed, Point lo, Point hi) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(lo.x, hi.x), uy(lo.y, hi.y);
  std::vector<Point> p(n);
  for (Point& q : p) q = {ux(rng), uy(rng)};
  return p;
}

replay::LogHeader header(const std::string& algorithm, std::size_t input_vertices) {
  replay::LogHeader h;
  h.input = "generated";
  h.input_hash = "0000000000000000";
  h.algorithm = algorithm;
  h.parameters = "input_vertices=" + std::to_string(input_vertices) + " first_index=0";
  h.data_structure = "tds";
  h.insertion = "flip";
  return h;
}

const std::string kPlate = std::string(MESHSTEP_ASSETS) + "/examples/plate.poly";

// ---------------------------------------------------------------------------------------
// A log that breaks the Delaunay property at a known step. 20 points near the origin are
// inserted (steps 1..18: the first triangle with three of them, then one step per vertex),
// then step 19 flips an interior edge that is strictly locally Delaunay in a strictly
// convex quadrilateral, so the new diagonal is strictly not Delaunay but the mesh stays
// valid; then 60 points far to the right are inserted (steps 20..79), which leave that edge
// alone. So the mesh after 18 steps holds and the mesh after 19 steps, and every later
// one, is not Delaunay: step 19 broke it, in the one numbering of step_numbers.hpp.
constexpr std::size_t kNear = 20, kFar = 60;
constexpr std::uint64_t kBadStep = kNear - 1;      // as every command numbers steps
constexpr std::uint64_t kSteps = kBadStep + kFar;  // 79

void write_broken_log(const std::string& path) {
  replay::LogWriter writer(path, header("broken-on-purpose", kNear + kFar));
  Triangulation<Tds, replay::Recorder> tri(uniform(kNear, 7, {0, 0}, {1, 1}), Insertion::flip,
                                           replay::Recorder(writer));
  tri.insert_all();
  Tds& mesh = tri.mesh();
  // The edge to flip: of those that qualify, the one whose quadrilateral lies farthest to
  // the left, out of the way of the points to come.
  HalfEdge chosen = kNone;
  double chosen_x = 0.0;
  for (FaceId f = 0; f < mesh.face_capacity(); ++f) {
    if (!mesh.is_live(f) || tri.is_ghost(f)) continue;
    HalfEdge h = mesh.half_edge(f);
    for (int i = 0; i < 3; ++i, h = mesh.next(h)) {
      const HalfEdge t = mesh.twin(h);
      if (t == kNone || tri.is_ghost(mesh.face(t))) continue;
      const Point &a = tri.point(mesh.origin(h)), &b = tri.point(mesh.dest(h)), &c = tri.point(mesh.apex(h)),
                  &d = tri.point(mesh.apex(t));
      const double oa = orient2d(c, d, a), ob = orient2d(c, d, b);
      const bool convex = (oa < 0.0 && ob > 0.0) || (oa > 0.0 && ob < 0.0);
      if (!convex || !(incircle(a, b, c, d) < 0.0)) continue;
      const double x = std::max({a.x, b.x, c.x, d.x});
      if (chosen == kNone || x < chosen_x) {
        chosen = h;
        chosen_x = x;
      }
    }
  }
  ASSERT_NE(chosen, kNone) << "no edge to flip in the test's point set";
  tri.recorder().step_begin(mesh, replay::StepKind::refine);
  tri.flip(chosen, replay::FlipReason::delaunay);
  HalfEdge hint = mesh.vertex_half_edge(0);
  for (const Point& p : uniform(kFar, 8, {10, 0}, {11, 1})) hint = tri.insert(tri.add_point(p), hint);
  tri.recorder().run_end(mesh);
  writer.finish();
}

class LogCheckBroken : public ::testing::Test {
 protected:
  void SetUp() override {
    write_broken_log(path_);
    if (HasFatalFailure()) return;
    log_.emplace(path_);
  }
  const replay::LogReader& log() const { return *log_; }
  replay::InvariantReport check(std::uint64_t every, std::vector<Invariant> invariants = {Invariant::valid, Invariant::delaunay}) const {
    replay::InvariantCheckOptions o;
    o.every = every;
    o.invariants = std::move(invariants);
    return replay::check_invariants(log(), o);
  }

  TempDir dir_{"meshstep_log_check_"};
  const std::string path_ = dir_.file("broken.mslog");
  std::optional<replay::LogReader> log_;
};

// What the test relies on, checked one boundary at a time with the checker itself: the
// log has the steps it should, boundaries before kBadStep hold, every later one is valid but
// not Delaunay.
TEST_F(LogCheckBroken, TheLogBreaksDelaunayAtTheKnownStepAndStaysBroken) {
  ASSERT_EQ(log().step_count(), kSteps);
  ASSERT_EQ(log().event(log().step_start(kBadStep - 1)).code, static_cast<std::uint8_t>(replay::StepKind::refine));
  replay::Replay r(log());
  for (std::uint64_t k = 0; k <= kSteps; ++k) {
    r.seek_step(k);
    const TriMesh mesh = r.mesh();
    EXPECT_TRUE(check_mesh(mesh, nullptr, {.delaunay = false}).ok) << "after " << k << " steps";
    EXPECT_EQ(check_mesh(mesh).ok, k < kBadStep) << "after " << k << " steps";
  }
}

TEST_F(LogCheckBroken, EveryBoundaryFindsTheStep) {
  for (const std::uint64_t every : std::vector<std::uint64_t>{0, 1}) {  // 0: automatic, every boundary for so short a run
    const replay::InvariantReport r = check(every);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.stride, 1u);
    EXPECT_EQ(r.boundary, kBadStep);  // the mesh after the bad step
    EXPECT_TRUE(r.previous_holds);
    EXPECT_EQ(r.checked, kBadStep + 1);    // 0..kBadStep, then it stops
    ASSERT_EQ(r.broken.size(), 1u);
    EXPECT_EQ(r.broken[0].invariant, Invariant::delaunay);
    EXPECT_EQ(r.broken[0].problem_count, 1u);
    ASSERT_EQ(r.broken[0].problems.size(), 1u);
    EXPECT_TRUE(contains(r.broken[0].problems[0], "is not Delaunay")) << r.broken[0].problems[0];
  }
}

TEST_F(LogCheckBroken, BisectionFindsTheStepBetweenCoarserSamples) {
  // Strides that put the bad boundary (19) strictly between two samples, and one that
  // samples only the start and the end.
  for (const std::uint64_t every : std::vector<std::uint64_t>{3, 7, 16, 50, 1000}) {
    const replay::InvariantReport r = check(every);
    EXPECT_FALSE(r.ok) << every;
    EXPECT_EQ(r.stride, every);
    EXPECT_EQ(r.boundary, kBadStep) << "every " << every;
    EXPECT_TRUE(r.previous_holds);
    EXPECT_LT(r.checked, kBadStep + 1) << "every " << every << ": bisection should check fewer boundaries";
    ASSERT_EQ(r.broken.size(), 1u);
    EXPECT_EQ(r.broken[0].invariant, Invariant::delaunay);
  }
}

TEST_F(LogCheckBroken, InvariantsAndRangeAreHonoured) {
  EXPECT_TRUE(check(1, {Invariant::valid}).ok);  // the flip leaves a valid mesh
  EXPECT_EQ(check(5, {Invariant::delaunay}).boundary, kBadStep);

  replay::InvariantCheckOptions o;
  o.to = kBadStep - 1;  // the mesh before the bad step: all hold
  replay::InvariantReport r = replay::check_invariants(log(), o);
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.checked, kBadStep);
  EXPECT_EQ(r.to, kBadStep - 1);

  o.from = kBadStep + 4;  // the range starts broken: nothing before it to bisect into
  o.to = UINT64_MAX;
  o.every = 10;
  r = replay::check_invariants(log(), o);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.boundary, kBadStep + 4);
  EXPECT_FALSE(r.previous_holds);
  EXPECT_EQ(r.checked, 1u);
}

// ---------------------------------------------------------------------------------------
// Recorded runs of the real algorithms hold both invariants at every boundary.

TEST(LogCheckRecorded, TriangulationAndRefinementHoldAtEveryStep) {
  TempDir dir("meshstep_log_check_");
  const Pslg plate = io::read_pslg(kPlate);
  for (const Insertion insertion : {Insertion::flip, Insertion::cavity}) {
    SCOPED_TRACE(to_string(insertion));
    const std::string cdt = dir.file("cdt.mslog"), refined = dir.file("refined.mslog");
    {
      replay::LogWriter writer(cdt, header("triangulate", plate.points.size()));
      TriangulateOptions options;
      options.insertion = insertion;
      options.record = &writer;
      triangulate(plate, options);
      writer.finish();
    }
    {
      replay::LogWriter writer(refined, header("circumcenter", plate.points.size()));
      RefineOptions options;
      options.criteria.min_angle_deg = 30.0;
      options.triangulate.insertion = insertion;
      options.triangulate.record = &writer;
      refine(plate, options);
      writer.finish();
    }
    for (const std::string& path : {cdt, refined}) {
      const replay::LogReader log(path);
      ASSERT_GT(log.step_count(), 10u);
      replay::InvariantCheckOptions o;
      o.every = 1;
      const replay::InvariantReport r = replay::check_invariants(log, o);
      EXPECT_TRUE(r.ok) << path << ": after " << r.boundary << " steps: "
                        << (r.broken.empty() ? "" : r.broken[0].problems.front());
      EXPECT_EQ(r.checked, log.step_count() + 1);
    }
  }
}

// Longest-edge bisection is valid at every step, and not Delaunay: the check says so, and
// bisection (coarse samples) and every-step checking agree on the step.
TEST(LogCheckRecorded, LeppBisectionIsValidButNotDelaunay) {
  TempDir dir("meshstep_log_check_");
  const Pslg plate = io::read_pslg(kPlate);
  const std::string path = dir.file("bisection.mslog");
  {
    replay::LogWriter writer(path, header("lepp-bisection", plate.points.size()));
    RefineOptions options;
    options.algorithm = "lepp-bisection";
    options.insertion = RefineInsertion::bisection;
    options.criteria.max_area = 0.5;
    options.triangulate.record = &writer;
    refine(plate, options);
    writer.finish();
  }
  const replay::LogReader log(path);
  replay::InvariantCheckOptions o;
  o.every = 1;
  o.invariants = {Invariant::valid};
  EXPECT_TRUE(replay::check_invariants(log, o).ok);
  o.invariants = {Invariant::delaunay};
  const replay::InvariantReport every = replay::check_invariants(log, o);
  ASSERT_FALSE(every.ok);
  // The step that broke it bisects a triangle.
  EXPECT_EQ(log.event(log.step_start(every.boundary - 1)).code, static_cast<std::uint8_t>(replay::StepKind::bisect));
}

// Past kAutoSamples steps, the automatic sampling spreads about kAutoSamples checks evenly
// (small meshes: the triangle budget does not bind), the last boundary included.
TEST(LogCheckRecorded, AutomaticSamplingOfALongerRun) {
  TempDir dir("meshstep_log_check_");
  const std::string path = dir.file("points.mslog");
  Pslg points;
  points.points = uniform(2100, 11, {0, 0}, {1, 1});
  {
    replay::LogWriter writer(path, header("triangulate", points.points.size()));
    TriangulateOptions options;
    options.record = &writer;
    triangulate(points, options);
    writer.finish();
  }
  const replay::LogReader log(path);
  ASSERT_EQ(log.step_count(), 2099u);  // the first triangle, then one step per vertex
  ASSERT_LT(std::uint64_t{2 * 2100 * replay::kAutoSamples}, replay::kAutoTriangles);
  replay::InvariantCheckOptions o;
  o.invariants = {Invariant::delaunay};
  std::vector<std::uint64_t> seen;
  o.progress = [&](std::uint64_t boundary, std::uint64_t) { seen.push_back(boundary); };
  const replay::InvariantReport r = replay::check_invariants(log, o);
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.stride, 2u);
  EXPECT_EQ(r.checked, 1051u);  // 0, 2, ..., 2098 and 2099
  ASSERT_EQ(seen.size(), r.checked);
  EXPECT_EQ(seen.front(), 0u);
  EXPECT_EQ(seen[1], 2u);
  EXPECT_EQ(seen.back(), 2099u);
}

// ---------------------------------------------------------------------------------------
// The invariants of one mesh, and their names.

TEST(LogCheckInvariants, OneMesh) {
  TriMesh quad;
  // A convex quadrilateral split along its longer diagonal: valid, not Delaunay.
  quad.points = {{0, 0}, {4, 0}, {4.5, 1}, {0.5, 1}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  std::vector<replay::BrokenInvariant> broken = replay::check_invariants(quad, {Invariant::valid, Invariant::delaunay});
  ASSERT_EQ(broken.size(), 1u);
  EXPECT_EQ(broken[0].invariant, Invariant::delaunay);
  EXPECT_TRUE(replay::check_invariants(quad, {Invariant::valid}).empty());
  // Constrained, the same edge is fine.
  quad.segments = {{0, 2, 1}};
  EXPECT_TRUE(replay::check_invariants(quad, {Invariant::delaunay}).empty());
  // A clockwise triangle breaks validity only.
  quad.segments.clear();
  quad.triangles = {{0, 2, 1}};
  broken = replay::check_invariants(quad, {Invariant::delaunay, Invariant::valid});
  ASSERT_EQ(broken.size(), 1u);
  EXPECT_EQ(broken[0].invariant, Invariant::valid);
  EXPECT_TRUE(contains(broken[0].problems.at(0), "clockwise")) << broken[0].problems[0];
}

TEST(LogCheckInvariants, Names) {
  EXPECT_EQ(replay::parse_invariants("valid,delaunay"), (std::vector<Invariant>{Invariant::valid, Invariant::delaunay}));
  EXPECT_EQ(replay::parse_invariants("delaunay,valid,delaunay"),
            (std::vector<Invariant>{Invariant::delaunay, Invariant::valid}));
  EXPECT_EQ(replay::parse_invariants("valid"), std::vector<Invariant>{Invariant::valid});
  for (const char* bad : {"", "valid,", "delaunay,segments", "Valid"}) {
    try {
      replay::parse_invariants(bad);
      ADD_FAILURE() << "'" << bad << "' was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_TRUE(contains(e.what(), "known: valid, delaunay")) << e.what();
    }
  }
}

// ---------------------------------------------------------------------------------------
// The command line.

class LogCheckCli : public testing::CliTest {
 protected:
  LogCheckCli() : CliTest("meshstep_log_check_cli_") {}
};

TEST_F(LogCheckCli, RecordedRunHolds) {
  const std::string log = dir_.file("plate.mslog");
  CommandResult r = meshstep("refine " + kPlate + " --min-angle 30 --record " + log + " --no-output -q");
  ASSERT_EQ(r.status, 0) << r.err;
  r = meshstep("log check " + log);
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, log + ": ")) << r.out;
  EXPECT_TRUE(contains(r.out, "step boundaries checked, valid,delaunay hold at each")) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;  // no progress when standard error is a file

  r = meshstep("log check " + log + " --json --every 3");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "\"ok\":true")) << r.out;
  EXPECT_TRUE(contains(r.out, "\"stride\":3")) << r.out;
}

TEST_F(LogCheckCli, BrokenLogNamesTheStep) {
  const std::string log = dir_.file("broken.mslog");
  write_broken_log(log);
  const std::string step = "step " + std::to_string(kBadStep) + " (events ";
  for (const std::string options : {"", " --every 1", " --every 9", " --invariant delaunay"}) {
    const CommandResult r = meshstep("log check " + log + options);
    EXPECT_EQ(r.status, 1) << options << ": " << r.out << r.err;
    EXPECT_TRUE(contains(r.out, log + ": " + step)) << options << ": " << r.out;
    EXPECT_TRUE(contains(r.out, ", refine) breaks delaunay: edge (")) << r.out;
    EXPECT_TRUE(contains(r.out, "step " + std::to_string(kBadStep - 1) + " holds")) << r.out;
    EXPECT_TRUE(contains(r.out, "--step " + std::to_string(kBadStep) + "' writes")) << r.out;
  }
  CommandResult r = meshstep("log check " + log + " --json --every 9");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(contains(r.out, "\"ok\":false")) << r.out;
  EXPECT_TRUE(contains(r.out, "\"step\":" + std::to_string(kBadStep) + ",")) << r.out;
  EXPECT_TRUE(contains(r.out, "\"step_kind\":\"refine\"")) << r.out;
  EXPECT_TRUE(contains(r.out, "\"broken\":{\"delaunay\":{\"problem_count\":1,")) << r.out;

  r = meshstep("log check " + log + " --invariant valid");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, std::to_string(kSteps + 1) + " step boundaries checked, valid holds at each")) << r.out;
  r = meshstep("log check " + log + " --to " + std::to_string(kBadStep - 1));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  r = meshstep("log check " + log + " --to " + std::to_string(kBadStep));
  EXPECT_EQ(r.status, 1) << r.out << r.err;
}

TEST_F(LogCheckCli, UsageAndInputErrors) {
  const std::string log = dir_.file("broken.mslog");
  write_broken_log(log);
  CommandResult r = meshstep("log check " + log + " --invariant valid,segments");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "meshstep: error: --invariant valid,segments: unknown invariant 'segments' "
                              "(known: valid, delaunay)"))
      << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;

  for (const std::string& range :
       std::vector<std::string>{" --from 5 --to 3", " --to " + std::to_string(kSteps + 1), " --from -1", " --every -2"}) {
    r = meshstep("log check " + log + range);
    EXPECT_EQ(r.status, 2) << range << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "meshstep: error: ")) << r.err;
  }

  const std::string missing = dir_.file("missing.mslog");
  r = meshstep("log check " + missing);
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "meshstep: error: " + missing + ": ")) << r.err;

  const std::string text = dir_.write("not_a_log.mslog", "hello\n");
  r = meshstep("log check " + text);
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "meshstep: error: " + text + ": ")) << r.err;
}

}  // namespace
}  // namespace meshstep
