// Refinement that keeps segments whole (RefineOptions::segment_splits, Triangle's -Y and
// -YY): the segments kept are exactly the input's, the mesh is still a valid constrained
// Delaunay triangulation of the input, every run ends (nasty inputs, every Delaunay
// algorithm, both data structures), and the report counts what is left over the bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "meshstep/check/mesh_check.hpp"
#include "meshstep/error.hpp"
#include "meshstep/geometry/predicates.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "meshstep/replay/run_header.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

Edge edge(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

std::set<Edge> segment_set(const std::vector<Segment>& segments) {
  std::set<Edge> out;
  for (const Segment& s : segments) out.insert(edge(s.a, s.b));
  return out;
}

// The edges of the mesh with a triangle on one side only: the domain's boundary, found from
// the triangles alone (not from what the mesh says of its segments).
std::set<Edge> boundary_edges(const TriMesh& m) {
  std::map<Edge, int> uses;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) ++uses[edge(t[i], t[(i + 1) % 3])];
  std::set<Edge> out;
  for (const auto& [e, n] : uses)
    if (n == 1) out.insert(e);
  return out;
}

double min_angle_deg(const TriMesh& m, std::size_t t) {
  double smallest = 180.0;
  for (int i = 0; i < 3; ++i) {
    const Point& o = m.points[m.triangles[t][i]];
    const Point& p = m.points[m.triangles[t][(i + 1) % 3]];
    const Point& q = m.points[m.triangles[t][(i + 2) % 3]];
    const double ux = p.x - o.x, uy = p.y - o.y, vx = q.x - o.x, vy = q.y - o.y;
    smallest = std::min(smallest, std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180.0 / std::numbers::pi);
  }
  return smallest;
}

Pslg polygon(std::vector<Point> points) {
  Pslg p;
  p.points = std::move(points);
  const auto n = static_cast<std::uint32_t>(p.points.size());
  for (std::uint32_t i = 0; i < n; ++i) p.segments.push_back({i, (i + 1) % n, 1});
  return p;
}

// A unit square cut by an interior segment (triangles on both sides), with a square hole.
Pslg square_with_interior_segment_and_hole() {
  Pslg p = polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const auto add = [&](Point a, Point b, int marker) {
    const auto i = static_cast<std::uint32_t>(p.points.size());
    p.points.push_back(a);
    p.points.push_back(b);
    p.segments.push_back({i, i + 1, marker});
    return i;
  };
  add({0.1, 0.5}, {0.9, 0.5}, 2);
  const std::uint32_t h = add({0.6, 0.7}, {0.8, 0.7}, 3);
  add({0.8, 0.85}, {0.6, 0.85}, 3);
  p.segments.push_back({h + 1, h + 2, 3});
  p.segments.push_back({h + 3, h, 3});
  p.holes.push_back({0.7, 0.78});
  return p;
}

// A 5-degree wedge, closed by an arc of three segments.
Pslg wedge_5_degrees() {
  const double r = std::numbers::pi / 180.0;
  return polygon({{0, 0}, {1, 0}, {std::cos(2.5 * r), std::sin(2.5 * r)}, {std::cos(5 * r), std::sin(5 * r)}});
}

// A block with spikes of 15, 12 and 8 degrees on its top, and a vertex a hair off its
// straight bottom edge.
Pslg small_angles_and_near_collinear() {
  std::vector<Point> points = {{0, 0}, {2, 1e-9}, {4, 0}, {4, 1}};
  for (const auto& [right, degrees] : {std::pair{3.2, 15.0}, {2.0, 12.0}, {0.6, 8.0}}) {
    const double height = 0.2 / std::tan(degrees / 2.0 * std::numbers::pi / 180.0);
    points.insert(points.end(), {{right, 1}, {right - 0.2, 1 + height}, {right - 0.4, 1}});
  }
  points.push_back({0, 1});
  return polygon(std::move(points));
}

double box_area(const Pslg& p) {
  double x0 = p.points[0].x, x1 = x0, y0 = p.points[0].y, y1 = y0;
  for (const Point& q : p.points) {
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  return (x1 - x0) * (y1 - y0);
}

struct Named {
  std::string name;
  Pslg pslg;
};

std::vector<Named> nasty_inputs() {
  std::vector<Named> inputs = {{"square", square_with_interior_segment_and_hole()},
                               {"wedge5", wedge_5_degrees()},
                               {"spikes", small_angles_and_near_collinear()}};
  const auto corpus = testing::shared_data() / "pslg";
  for (const char* name : {"guitar.poly", "A.poly"})
    if (std::filesystem::exists(corpus / name)) inputs.push_back({name, io::read_pslg((corpus / name).string())});
  return inputs;
}

// The algorithm's own kind of bound at 30 degrees (a size-only one: a 500th of `area`).
RefineOptions options(const AlgorithmInfo& algorithm, SegmentSplits splits, DataStructure ds, double area = 1.0) {
  RefineOptions o = options_for(algorithm);
  o.segment_splits = splits;
  o.triangulate.data_structure = ds;
  o.criteria.min_angle_deg = algorithm.default_min_angle_deg > 0.0 ? 30.0 : 0.0;
  o.criteria.max_aspect = algorithm.default_max_aspect;
  if (algorithm.aspect_then_angle) o.phases = aspect_then_angle_phases(o.criteria, algorithm);
  if (algorithm.default_min_angle_deg == 0.0 && algorithm.default_max_aspect == 0.0) o.criteria.max_area = area / 500.0;
  o.criteria.max_steiner = 2'000'000;  // a safety net only: every run must end well before
  return o;
}

// Every Delaunay algorithm, both data structures, both modes, on every nasty input: the run
// ends by itself, the mesh is a valid constrained Delaunay triangulation of the input, the
// kept segments are the input's (all of them for none, the boundary's for interior), and
// the report's count of triangles under the angle bound is the mesh's.
TEST(SegmentSplits, KeptSegmentsAreTheInputsOnEveryAlgorithmAndDataStructure) {
  const std::vector<Named> inputs = nasty_inputs();
  for (const Named& in : inputs) {
    // The boundary of the unrefined domain: what interior mode must leave as it is.
    const std::set<Edge> input_boundary = boundary_edges(triangulate(in.pslg));
    for (const AlgorithmInfo& algorithm : algorithms()) {
      if (algorithm.insertion == RefineInsertion::bisection) continue;  // refused: its own test
      for (const SegmentSplits splits : {SegmentSplits::interior, SegmentSplits::none})
        for (const DataStructure ds : {DataStructure::tds, DataStructure::dcel}) {
          SCOPED_TRACE(in.name + " " + std::string(algorithm.name) + " " + to_string(splits) + " " + to_string(ds));
          const RefineOptions o = options(algorithm, splits, ds, box_area(in.pslg));
          RefineReport report;
          const TriMesh m = refine(in.pslg, o, &report);
          EXPECT_FALSE(report.stopped_by_cap);
          const CheckReport check = check_mesh(m, &in.pslg);
          EXPECT_TRUE(check.ok) << (check.problems.empty() ? std::string() : check.problems.front());
          EXPECT_EQ(boundary_edges(m), input_boundary);
          if (splits == SegmentSplits::none) {
            EXPECT_EQ(segment_set(m.segments), segment_set(in.pslg.segments));
            EXPECT_EQ(m.segments.size(), in.pslg.segments.size());
            EXPECT_EQ(report.segment_splits, 0u);
          }
          const double bound = o.phases.empty() ? o.criteria.min_angle_deg : o.phases.back().criteria.min_angle_deg;
          std::size_t below = 0;
          for (std::size_t t = 0; t < m.triangles.size(); ++t) below += min_angle_deg(m, t) < bound - 1e-9;
          EXPECT_EQ(report.below_min_angle, below);
          EXPECT_EQ(report.bounds_met, report.bad_triangles == 0);
          EXPECT_GE(report.bad_triangles, report.below_min_angle);
        }
    }
  }
}

// Without the mode the same runs do split the boundary (the tests above would then fail),
// and with interior the segment inside the square is split all the same.
TEST(SegmentSplits, DefaultSplitsTheBoundaryAndInteriorSplitsOnlyInteriorSegments) {
  const Pslg in = square_with_interior_segment_and_hole();
  const std::set<Edge> input_boundary = boundary_edges(triangulate(in));
  RefineOptions o = options(*find_algorithm("offcenter"), SegmentSplits::all, DataStructure::tds);
  RefineReport all_report;
  const TriMesh all = refine(in, o, &all_report);
  EXPECT_NE(boundary_edges(all), input_boundary);
  EXPECT_GT(boundary_edges(all).size(), input_boundary.size());
  EXPECT_TRUE(all_report.bounds_met);
  EXPECT_EQ(all_report.kept_segment_refusals, 0u);

  o.segment_splits = SegmentSplits::interior;
  RefineReport report;
  const TriMesh interior = refine(in, o, &report);
  EXPECT_EQ(boundary_edges(interior), input_boundary);
  EXPECT_GT(report.segment_splits, 0u);
  // The interior segment (input vertices 4 and 5) is in pieces: a Steiner vertex lies on it.
  EXPECT_FALSE(segment_set(interior.segments).contains(edge(4, 5)));
  std::size_t on_interior_segment = 0;
  for (const Segment& s : interior.segments) on_interior_segment += s.marker == 2;
  EXPECT_GT(on_interior_segment, 1u);
}

// Keeping segments costs quality near them: on guitar.poly at 30 degrees some triangles are
// left over the bound, the report says how many (the mesh's own count) and why (refusals).
TEST(SegmentSplits, TheReportCountsTrianglesLeftOverTheBound) {
  const auto path = testing::shared_data() / "pslg" / "guitar.poly";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no shared corpus";
  const Pslg in = io::read_pslg(path.string());
  RefineOptions o = options(*find_algorithm("offcenter"), SegmentSplits::none, DataStructure::tds);
  RefineReport report;
  const TriMesh m = refine(in, o, &report);
  std::size_t below = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) below += min_angle_deg(m, t) < 30.0 - 1e-9;
  EXPECT_GT(below, 0u);
  EXPECT_EQ(report.below_min_angle, below);
  EXPECT_EQ(report.bad_triangles, below);
  EXPECT_FALSE(report.bounds_met);
  EXPECT_GT(report.kept_segment_refusals, 0u);
  // Fewer points than the conforming mesh, and the triangles away from the segments meet
  // the bound: refinement went on where it could.
  RefineReport all_report;
  o.segment_splits = SegmentSplits::all;
  const TriMesh all = refine(in, o, &all_report);
  EXPECT_LT(report.steiner_vertices, all_report.steiner_vertices);
  EXPECT_GT(report.steiner_vertices, 0u);
}

// Lepp beside kept segments: on A.poly every Lepp path ends at the boundary, whose
// terminal midpoints (and centroids beside it) are refused when the boundary is kept; the
// bad triangle's own point is inserted instead. Without that fallback both Lepp selections
// added no point at all under interior (offcenter adds 2). The run ends, and no vertex
// lands on a kept segment.
TEST(SegmentSplits, LeppFallsBackToTheBadTrianglesOwnPointBesideKeptSegments) {
  const auto path = testing::shared_data() / "pslg" / "A.poly";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no shared corpus";
  const Pslg in = io::read_pslg(path.string());
  const std::set<Edge> input_boundary = boundary_edges(triangulate(in));
  for (const char* name : {"lepp-centroid", "lepp-midpoint"})
    for (const SegmentSplits splits : {SegmentSplits::interior, SegmentSplits::none}) {
      SCOPED_TRACE(std::string(name) + " " + to_string(splits));
      const RefineOptions o = options(*find_algorithm(name), splits, DataStructure::tds);
      RefineReport report;
      const TriMesh m = refine(in, o, &report);
      EXPECT_FALSE(report.stopped_by_cap);
      EXPECT_GT(report.steiner_vertices, 0u);
      EXPECT_GT(m.points.size(), in.points.size());
      EXPECT_EQ(boundary_edges(m), input_boundary);
      if (splits == SegmentSplits::none) {
        EXPECT_EQ(segment_set(m.segments), segment_set(in.segments));
      }
      // No new vertex on an input segment (all of A.poly's are on its boundary).
      for (std::size_t v = in.points.size(); v < m.points.size(); ++v)
        for (const Segment& s : in.segments) {
          const Point &a = in.points[s.a], &b = in.points[s.b], &p = m.points[v];
          const bool collinear = orient2d(a, b, p) == 0.0;  // exact
          const bool within = std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
                              std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
          EXPECT_FALSE(collinear && within) << "vertex " << v << " on segment " << s.a << "-" << s.b;
        }
      const CheckReport check = check_mesh(m, &in);
      EXPECT_TRUE(check.ok) << (check.problems.empty() ? std::string() : check.problems.front());
    }
}

// The same mesh on both data structures (the refiner decides in the mesh's own order).
TEST(SegmentSplits, BothDataStructuresGiveTheSameMesh) {
  const Pslg in = small_angles_and_near_collinear();
  for (const SegmentSplits splits : {SegmentSplits::interior, SegmentSplits::none}) {
    const TriMesh tds = refine(in, options(*find_algorithm("offcenter"), splits, DataStructure::tds));
    const TriMesh dcel = refine(in, options(*find_algorithm("offcenter"), splits, DataStructure::dcel));
    EXPECT_EQ(canonical_triangles(tds), canonical_triangles(dcel)) << to_string(splits);
  }
}

// Bisection must cut whatever terminal edge it reaches: refused, in words that say so.
TEST(SegmentSplits, BisectionIsRefused) {
  RefineOptions o = options_for(*find_algorithm("lepp-bisection"));
  o.criteria.max_area = 0.01;
  o.segment_splits = SegmentSplits::interior;
  try {
    refine(polygon({{0, 0}, {1, 0}, {0, 1}}), o);
    FAIL() << "bisection with kept segments ran";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot keep segments whole"), std::string::npos) << e.what();
  }
  EXPECT_THROW(refine_options(parse_operation("refine --algorithm lepp-bisection --max-area 0.1 --split-segments none")),
               RunSpecError);
}

// The run description reads and prints the option; a word it does not know is refused.
TEST(SegmentSplits, RunDescriptionReadsAndPrintsIt) {
  const Operation op = parse_operation("refine --min-angle 30 --split-segments interior");
  EXPECT_EQ(op.segment_splits, SegmentSplits::interior);
  EXPECT_EQ(print_operation(op), "refine --min-angle 30 --split-segments interior");
  EXPECT_EQ(parse_operation(print_operation(op)), op);
  EXPECT_EQ(refine_options(op).segment_splits, SegmentSplits::interior);
  EXPECT_EQ(parse_operation("refine --split-segments all").segment_splits, SegmentSplits::all);
  EXPECT_EQ(print_operation(parse_operation("refine --split-segments all")), "refine");
  EXPECT_EQ(refine_options(parse_operation("refine --split-segments none")).segment_splits, SegmentSplits::none);
  EXPECT_THROW(parse_operation("refine --split-segments boundary"), RunSpecError);
  EXPECT_THROW(parse_operation("triangulate --split-segments none"), RunSpecError);
}

// A log's header says when segments were kept, and only then (every other header stays as
// it was).
TEST(SegmentSplits, TheLogHeaderSaysWhichSegmentsWereKept) {
  RefineOptions o = options_for(*find_algorithm("offcenter"));
  EXPECT_EQ(replay::refine_parameters(o, "", 4, 0).find("split_segments"), std::string::npos);
  o.segment_splits = SegmentSplits::interior;
  EXPECT_NE(replay::refine_parameters(o, "", 4, 0).find(" split_segments=interior"), std::string::npos);
  o.segment_splits = SegmentSplits::none;
  EXPECT_NE(replay::refine_parameters(o, "", 4, 0).find(" split_segments=none"), std::string::npos);
}

// A caption names the mode when segments were kept (the run is not the default's), read
// back from the header as written; a run that splits them all is described as before.
TEST(SegmentSplits, TheRunsDescriptionNamesTheModeWhenSegmentsAreKept) {
  RefineOptions o = options_for(*find_algorithm("offcenter"));
  o.criteria.min_angle_deg = 30.0;
  replay::LogHeader header;
  header.algorithm = "offcenter";
  header.data_structure = "tds";
  header.parameters = replay::refine_parameters(o, "", 4, 0);
  EXPECT_EQ(replay::describe_run(header, replay::read_run_header(header, "run.log")), "offcenter, min angle 30");
  for (const SegmentSplits splits : {SegmentSplits::interior, SegmentSplits::none}) {
    o.segment_splits = splits;
    header.parameters = replay::refine_parameters(o, "", 4, 0);
    const replay::RunHeader run = replay::read_run_header(header, "run.log");
    EXPECT_EQ(run.segment_splits, splits);
    EXPECT_EQ(replay::describe_run(header, run), std::string("offcenter, min angle 30, split segments ") + to_string(splits));
  }
}

}  // namespace
}  // namespace meshstep
