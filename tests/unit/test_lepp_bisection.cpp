// Lepp longest-edge bisection (algorithm lepp-bisection): the area or size bound holds, the
// mesh is conforming after every step, no angle falls below half the starting mesh's
// smallest, and every data structure gives the same mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "meshstep/check/mesh_check.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/verify.hpp"
#include "temp_dir.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;

std::string shared_poly(const std::string& name) { return (testing::shared_data() / "pslg" / name).string(); }

RefineOptions bisection(double max_area) {
  RefineOptions o = options_for(*find_algorithm("lepp-bisection"));
  o.criteria.max_area = max_area;
  return o;
}

double area(const TriMesh& m, std::size_t t) {
  const Point &a = m.points[m.triangles[t][0]], &b = m.points[m.triangles[t][1]], &c = m.points[m.triangles[t][2]];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// The domain's area over n: a bound that asks for about n to 2n triangles.
double area_for(const Pslg& in, double n) {
  const TriMesh m = triangulate(in);
  double total = 0.0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) total += area(m, t);
  return total / n;
}


// Conforming (not Delaunay) and covering the input; the bound met everywhere; no angle
// below half the smallest angle of the constrained Delaunay triangulation it started from.
TriMesh bisect_checked(const Pslg& in, const RefineOptions& o, RefineReport& report) {
  const TriMesh m = refine(in, o, &report);
  CheckOptions conforming;
  conforming.delaunay = false;
  const CheckReport check = check_mesh(m, &in, conforming);
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? std::string() : check.problems.front());
  EXPECT_TRUE(report.bounds_met);
  EXPECT_FALSE(report.stopped_by_cap);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (o.criteria.max_area > 0.0) {
      EXPECT_LE(area(m, t), o.criteria.max_area) << "triangle " << t;
    }
  }
  const double start = angle_stats(triangulate(in)).min_angle_deg;
  EXPECT_GE(angle_stats(m).min_angle_deg, start / 2.0 - 1e-9) << "started at " << start << " degrees";
  EXPECT_EQ(report.steiner_vertices, m.points.size() - in.points.size());
  return m;
}

TEST(LeppBisection, NamedInputsEveryStructureAndOrder) {
  for (const std::string name : {"A.poly", "guitar.poly", "la.poly", "face.poly"}) {
    if (!fs::exists(shared_poly(name))) GTEST_SKIP() << shared_poly(name) << " is absent: skipped";
    const Pslg in = io::read_pslg(shared_poly(name));
    const double max_area = area_for(in, 3000.0);
    std::vector<std::array<std::uint32_t, 3>> reference;
    for (const RefineOrder order : {RefineOrder::worst_first, RefineOrder::fifo}) {
      reference.clear();
      for (const TriangulateOptions& t : testing::all_configurations()) {
        SCOPED_TRACE(name + " " + to_string(order) + " " + testing::describe(t));
        RefineOptions o = bisection(max_area);
        o.order = order;
        o.triangulate = t;
        RefineReport report;
        const TriMesh m = bisect_checked(in, o, report);
        EXPECT_GT(m.triangles.size(), 3000u);
        if (reference.empty()) reference = canonical_triangles(m);
        else EXPECT_EQ(canonical_triangles(m), reference);
      }
    }
  }
}

// A size function instead of an area bound: small edges near the origin, large far away.
TEST(LeppBisection, SizeFunctionBoundsTheLongestEdges) {
  Pslg in;
  in.points = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 4}, {5, 6}};
  in.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 2}, {5, 6, 2}, {6, 4, 2}};
  in.holes = {{5, 4.5}};
  const auto size = [](const Point& p) { return 0.2 + 0.2 * std::hypot(p.x, p.y); };
  RefineOptions o = options_for(*find_algorithm("lepp-bisection"));
  o.criteria.size = size;
  RefineReport report;
  const TriMesh m = bisect_checked(in, o, report);
  std::size_t near_origin = 0;
  for (const auto& t : m.triangles) {
    const Point &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    const Point centroid{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
    const double longest = std::max({std::hypot(a.x - b.x, a.y - b.y), std::hypot(b.x - c.x, b.y - c.y),
                                     std::hypot(c.x - a.x, c.y - a.y)});
    EXPECT_LE(longest, size(centroid) * (1.0 + 1e-12));
    near_origin += std::hypot(centroid.x, centroid.y) < 2.0;
  }
  EXPECT_GT(near_origin, 20u);
  // The hole stays empty and its segments keep their marker.
  for (const Segment& s : m.segments) EXPECT_TRUE(s.marker == 1 || s.marker == 2);
}

// Recorded: every step is one bisection, the log verifies, and the mesh after every step
// is conforming (no vertex inside an edge: the far side was bisected in the same step).
TEST(LeppBisection, ConformingAfterEveryRecordedStep) {
  Pslg in;
  in.points = {{0, 0}, {8, 0}, {8, 3}, {3, 3}, {3, 8}, {0, 8}, {1, 1}};
  for (std::uint32_t i = 0; i < 6; ++i) in.segments.push_back({i, (i + 1) % 6, 1});
  testing::TempDir dir("meshstep_bisection_");
  const std::string path = dir.file("bisection.mslog");
  RefineReport report;
  {
    replay::LogWriter writer(path, replay::LogHeader{});
    RefineOptions o = bisection(0.05);
    o.triangulate.record = &writer;
    refine(in, o, &report);
    writer.finish();
  }
  ASSERT_TRUE(report.bounds_met);
  const replay::LogReader log(path);
  const replay::VerifyReport v = replay::verify(log);
  ASSERT_TRUE(v.ok) << v.problem;
  replay::Replay cursor(log);
  CheckOptions conforming;
  conforming.delaunay = false;
  std::size_t bisections = 0, steps = 0;
  while (cursor.next_step()) {
    ++steps;
    const CheckReport check = check_mesh(cursor.mesh(), nullptr, conforming);
    ASSERT_TRUE(check.ok) << "after step " << steps << ": " << check.problems.front();
  }
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const replay::Event ev = log.event(e);
    if (ev.type == replay::EventType::step_begin && ev.code == static_cast<std::uint8_t>(replay::StepKind::bisect))
      ++bisections;
  }
  EXPECT_EQ(bisections, report.triangles_split);
  EXPECT_EQ(bisections, report.steiner_vertices);
  EXPECT_GT(bisections, 100u);
}

TEST(LeppBisection, AnglesAndMissingBoundsAreInputErrors) {
  Pslg in;
  in.points = {{0, 0}, {1, 0}, {0, 1}};
  RefineOptions o = bisection(0.0);
  EXPECT_THROW(refine(in, o), InputError);  // no size bound at all
  o.criteria.max_area = 0.01;
  o.criteria.min_angle_deg = 20.0;
  try {
    refine(in, o);
    FAIL() << "an angle bound was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--max-area or --size"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace meshstep
