// Delaunay triangulation of point sets, on every data structure and insertion strategy,
// including the degenerate inputs that break naive implementations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "meshstep/error.hpp"
#include "meshstep/geometry/predicates.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

using testing::triangulate_everywhere;

Pslg points(std::vector<Point> p) {
  Pslg in;
  in.points = std::move(p);
  return in;
}

// Number of input points on the convex hull boundary (collinear ones included), by
// Andrew's monotone chain with exact orientation: an independent count for Euler's formula.
std::size_t hull_boundary_points(std::vector<Point> p) {
  std::sort(p.begin(), p.end(), lex_less);
  p.erase(std::unique(p.begin(), p.end()), p.end());
  std::vector<Point> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const Point& q : p) {
      while (hull.size() >= base + 2 && orient2d(hull[hull.size() - 2], hull.back(), q) < 0.0)
        hull.pop_back();
      hull.push_back(q);
    }
    hull.pop_back();
    std::reverse(p.begin(), p.end());
  }
  return hull.size();
}

std::vector<Point> uniform(std::size_t n, std::uint64_t seed, double scale = 1.0, Point offset = {}) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> p(n);
  for (Point& q : p) q = {offset.x + scale * u(rng), offset.y + scale * u(rng)};
  return p;
}

TEST(Triangulate, EulerCountOnRandomPoints) {
  const auto p = uniform(3000, 7);
  const TriMesh m = triangulate_everywhere(points(p));
  EXPECT_EQ(m.triangles.size(), 2 * p.size() - hull_boundary_points(p) - 2);
}

TEST(Triangulate, IntegerGridIsCocircularEverywhere) {
  std::vector<Point> p;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) p.push_back({double(i), double(j)});
  const TriMesh m = triangulate_everywhere(points(p));
  EXPECT_EQ(m.triangles.size(), 2 * p.size() - hull_boundary_points(p) - 2);
  EXPECT_NEAR(angle_stats(m).min_angle_deg, 45.0, 1e-9);
}

TEST(Triangulate, ManyPointsOnOneCircleAndItsCentre) {
  // Integer points on x² + y² = 65² (65 = 5·13 has many representations), all cocircular.
  std::vector<Point> p{{0, 0}};
  for (int x = -65; x <= 65; ++x)
    for (int y = -65; y <= 65; ++y)
      if (x * x + y * y == 65 * 65) p.push_back({double(x), double(y)});
  ASSERT_GT(p.size(), 30u);
  const TriMesh m = triangulate_everywhere(points(p));
  EXPECT_EQ(m.triangles.size(), 2 * p.size() - hull_boundary_points(p) - 2);
}

TEST(Triangulate, DuplicatesAreMergedAndReported) {
  auto p = uniform(500, 3);
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; i += 2) p.push_back(p[i]);
  TriangulateReport report;
  const TriMesh m = triangulate_everywhere(points(p), false, &report);
  EXPECT_EQ(report.duplicate_vertices, (n + 1) / 2);
  ASSERT_EQ(report.warnings.size(), 1u);
  // The first duplicate in input order is vertex n, a copy of vertex 0, which stays.
  EXPECT_NE(report.warnings[0].find("vertex " + std::to_string(n) + " is at the same place as vertex 0"),
            std::string::npos)
      << report.warnings[0];
  for (const auto& t : m.triangles)
    for (const auto v : t) EXPECT_LT(v, n) << "a triangle uses a later duplicate";
  EXPECT_EQ(m.points.size(), p.size());  // still listed, in input order
  EXPECT_EQ(m.triangles.size(), 2 * n - hull_boundary_points(p) - 2);
}

// keep_mesh = false (meshstep triangulate --no-output) skips the conversion, not the
// triangulation: the report counts what the kept mesh holds, duplicates, crossings and
// carving included, on both data structures.
TEST(Triangulate, WithoutKeepingTheMeshTheReportCountsTheSame) {
  Pslg square;
  square.points = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 4}, {6, 6}, {4, 6}, {1, 1}, {9, 2}, {1, 1}};
  square.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 2}, {5, 6, 2}, {6, 7, 2}, {7, 4, 2},
                     {0, 2, 3}, {1, 3, 3}};  // the diagonals cross each other and the hole
  square.holes = {{5, 5}};
  auto scattered = points(uniform(700, 5));
  scattered.points.push_back(scattered.points[3]);
  for (const Pslg& input : {square, scattered}) {
    for (const DataStructure ds : {DataStructure::tds, DataStructure::dcel}) {
      TriangulateOptions options;
      options.data_structure = ds;
      TriangulateReport kept_report, counted_report;
      const TriMesh kept = triangulate(input, options, &kept_report);
      options.keep_mesh = false;
      const TriMesh counted = triangulate(input, options, &counted_report);
      EXPECT_TRUE(counted.points.empty() && counted.triangles.empty() && counted.segments.empty());
      EXPECT_EQ(counted_report.vertices, kept.points.size());
      EXPECT_EQ(counted_report.triangles, kept.triangles.size());
      EXPECT_EQ(counted_report.segments, kept.segments.size());
      EXPECT_EQ(kept_report.triangles, kept.triangles.size());
      EXPECT_EQ(counted_report.warnings, kept_report.warnings);
      EXPECT_EQ(counted_report.steiner_vertices, kept_report.steiner_vertices);
    }
  }
  EXPECT_GT(triangulate(square).segments.size(), square.segments.size());  // the crossings split them
}

TEST(Triangulate, CollinearPointsWithOneOffTheLine) {
  std::vector<Point> p;
  for (int i = 0; i < 50; ++i) p.push_back({i * 0.1, i * 0.2});
  p.push_back({0.0, 1.0});
  const TriMesh m = triangulate_everywhere(points(p));
  EXPECT_EQ(m.triangles.size(), 49u);  // a fan from the lone point
}

TEST(Triangulate, CollinearHullEdgesAndInteriorLines) {
  // A square whose sides carry many collinear points, with an interior diagonal line.
  std::vector<Point> p;
  for (int i = 0; i <= 20; ++i) {
    const double t = i / 20.0;
    p.insert(p.end(), {{t, 0}, {1, t}, {1 - t, 1}, {0, 1 - t}, {t, t}});
  }
  const TriMesh m = triangulate_everywhere(points(p));
  EXPECT_GT(m.triangles.size(), 0u);
}

TEST(Triangulate, TooFewOrDegenerateInputsAreReported) {
  const std::vector<std::vector<Point>> bad = {
      {},
      {{1, 1}},
      {{1, 1}, {1, 1}, {1, 1}},
      {{0, 0}, {1, 1}},
      {{0, 0}, {1, 1}, {2, 2}, {3, 3}, {1, 1}},
  };
  for (const auto& p : bad) {
    for (const TriangulateOptions& o : testing::all_configurations())
      EXPECT_THROW(triangulate(points(p), o), InputError) << p.size() << " points";
  }
  try {
    triangulate(points({{0, 0}, {1, 1}, {2, 2}}));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("one line"), std::string::npos) << e.what();
  }
}

TEST(Triangulate, NonFiniteCoordinatesAreRejected) {
  EXPECT_THROW(triangulate(points({{0, 0}, {1, 0}, {0, NAN}})), InputError);
  EXPECT_THROW(triangulate(points({{0, 0}, {1, 0}, {0, INFINITY}})), InputError);
}

// Scaling by a power of two changes no predicate: the triangles must be identical, at
// scales where naive incircle would overflow or underflow.
TEST(Triangulate, HugeAndTinyCoordinatesGiveTheSameTriangles) {
  std::vector<Point> p = uniform(400, 11);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) p.push_back({i / 9.0, j / 9.0});  // cocircular quads too
  const auto reference = canonical_triangles(triangulate_everywhere(points(p)));
  // The checker's own double-precision predicates overflow at these scales, so the proof
  // is the identity with the checked unit-scale triangulation.
  for (const int e : {-1000, -600, -300, 300, 600, 1000}) {
    std::vector<Point> q = p;
    for (Point& r : q) r = {std::ldexp(r.x, e), std::ldexp(r.y, e)};
    for (const TriangulateOptions& o : testing::all_configurations()) {
      const TriMesh m = triangulate(points(q), o);
      EXPECT_EQ(canonical_triangles(m), reference) << "scale 2^" << e << " " << testing::describe(o);
      EXPECT_EQ(m.points, q);  // coordinates come back bit for bit
    }
  }
}

std::size_t distinct(std::vector<Point> p) {
  std::sort(p.begin(), p.end(), lex_less);
  return static_cast<std::size_t>(std::unique(p.begin(), p.end()) - p.begin());
}

TEST(Triangulate, TinyClusterFarFromTheOrigin) {
  // A 1e-8-wide cluster at 1e6, where one ulp is 1.2e-10: coordinates take only about a
  // hundred values per axis, so there are many duplicates and collinear/cocircular sets.
  std::vector<Point> p = uniform(3000, 5, 1e-8, {1e6, -1e6});
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) p.push_back({1e6 + i * 2.5e-10, -1e6 + j * 2.5e-10});
  TriangulateReport report;
  const TriMesh m = triangulate_everywhere(points(p), false, &report);
  const std::size_t n = distinct(p);
  EXPECT_EQ(report.duplicate_vertices, p.size() - n);
  EXPECT_EQ(m.triangles.size(), 2 * n - hull_boundary_points(p) - 2);
}

TEST(Triangulate, ClusterPlusFarPointsIsValid) {
  std::vector<Point> p = uniform(3000, 9, 1e-6);
  p.push_back({1e6, 1e6});
  p.push_back({-1e6, 1e6});
  p.push_back({0, -1e6});
  triangulate_everywhere(points(p));
}

TEST(Triangulate, DeterministicAcrossRuns) {
  const Pslg in = points(uniform(5000, 21));
  const TriMesh a = triangulate(in), b = triangulate(in);
  EXPECT_EQ(a.triangles, b.triangles);  // same order, not just the same set
}

}  // namespace
}  // namespace meshstep
