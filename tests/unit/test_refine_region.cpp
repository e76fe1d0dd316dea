// Refinement limited to a region (RefineOptions::region): the region value type (parsing,
// refusals, the exact point-in-region test with its border), and runs whose bounds hold for
// every triangle with its centroid in the region and not elsewhere, on every data structure
// and insertion, with bisection, and on an existing mesh (refine_mesh).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "meshstep/check/mesh_check.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/error.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/region.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

std::string refusal(auto&& make) {
  try {
    make();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(RefineRegion, ParsesABoxAndRefusesMalformedNonFiniteAndEmptyOnes) {
  const RefineRegion r = RefineRegion::parse_box(" 1, -2.5,3e0 ,4");
  EXPECT_EQ(r.kind(), RefineRegion::Kind::box);
  EXPECT_EQ(r.low(), (Point{1, -2.5}));
  EXPECT_EQ(r.high(), (Point{3, 4}));
  EXPECT_EQ(r.text(), "box:1,-2.5,3,4");
  for (const char* bad : {"", "1,2,3", "1,2,3,4,5", "a,b,c,d", "1,2,,4", "1;2;3;4", "1,2,3,4x"})
    EXPECT_TRUE(has(refusal([&] { RefineRegion::parse_box(bad); }), "X0,Y0,X1,Y1 (four numbers")) << bad;
  for (const char* bad : {"inf,0,1,1", "0,nan,1,1", "0,0,1e999,1"})
    EXPECT_TRUE(has(refusal([&] { RefineRegion::parse_box(bad); }), "must be finite numbers")) << bad;
  for (const char* bad : {"1,0,0,1", "0,0,0,1", "0,2,1,2"})
    EXPECT_TRUE(has(refusal([&] { RefineRegion::parse_box(bad); }), "is empty: X0 must be below X1")) << bad;
}

TEST(RefineRegion, ABoxHoldsItsBorder) {
  const RefineRegion r = RefineRegion::box({0, 0}, {2, 1});
  EXPECT_TRUE(r.contains({0, 0}));
  EXPECT_TRUE(r.contains({2, 0.5}));
  EXPECT_TRUE(r.contains({1, 1}));
  EXPECT_FALSE(r.contains({std::nextafter(2.0, 3.0), 0.5}));
  EXPECT_FALSE(r.contains({1, std::nextafter(0.0, -1.0)}));
}

// An L (concave), given clockwise: the notch is outside, the border (slanted edges too) is
// inside, to the last bit.
TEST(RefineRegion, APolygonDecidesExactlyWithItsBorderIn) {
  const RefineRegion l = RefineRegion::polygon({{0, 0}, {0, 3}, {1, 3}, {1, 1}, {3, 1}, {3, 0}});
  EXPECT_EQ(l.kind(), RefineRegion::Kind::polygon);
  EXPECT_EQ(l.low(), (Point{0, 0}));
  EXPECT_EQ(l.high(), (Point{3, 3}));
  EXPECT_TRUE(l.contains({0.5, 2.5}));
  EXPECT_TRUE(l.contains({2.5, 0.5}));
  EXPECT_FALSE(l.contains({2, 2}));  // the notch
  EXPECT_TRUE(l.contains({1, 2}));   // on an edge
  EXPECT_TRUE(l.contains({1, 1}));   // at the reflex vertex
  EXPECT_TRUE(l.contains({3, 0}));   // at a corner
  EXPECT_FALSE(l.contains({std::nextafter(1.0, 2.0), 2}));
  // Counterclockwise whatever the input's order.
  const auto& v = l.vertices();
  double twice = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) twice += v[i].x * v[(i + 1) % v.size()].y - v[(i + 1) % v.size()].x * v[i].y;
  EXPECT_GT(twice, 0.0);
  // A slanted edge from (0, 0) to (3, 1): (1.5, 0.5) is on it exactly, the next double
  // below is outside, the next above inside.
  const RefineRegion t = RefineRegion::polygon({{0, 0}, {3, 1}, {0, 1}});
  EXPECT_TRUE(t.contains({1.5, 0.5}));
  EXPECT_FALSE(t.contains({1.5, std::nextafter(0.5, 0.0)}));
  EXPECT_TRUE(t.contains({1.5, std::nextafter(0.5, 1.0)}));
  EXPECT_TRUE(has(t.text(), "polygon:0,0;3,1;0,1")) << t.text();
}

TEST(RefineRegion, RefusesPolygonsThatAreNotSimple) {
  EXPECT_TRUE(has(refusal([] { RefineRegion::polygon({{0, 0}, {1, 0}}); }), "at least 3 vertices"));
  EXPECT_TRUE(has(refusal([] { RefineRegion::polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 2}, {1, 1}}); }),
                  "touch or cross"));
  EXPECT_TRUE(has(refusal([] { RefineRegion::polygon({{0, 0}, {2, 2}, {2, 0}, {0, 2}}); }), "touch or cross"));
  EXPECT_TRUE(has(refusal([] { RefineRegion::polygon({{0, 0}, {2, 0}, {1, 0}}); }), "overlap"));
  EXPECT_TRUE(has(refusal([] { RefineRegion::polygon({{0, 0}, {1, 0}, {1, 0}, {0, 1}}); }), "length zero"));
  EXPECT_TRUE(has(refusal([] { RefineRegion::polygon({{0, 0}, {NAN, 0}, {0, 1}}); }), "finite"));
}

Pslg ring_pslg(std::vector<Point> points, std::vector<Segment> segments) {
  Pslg p;
  p.points = std::move(points);
  p.segments = std::move(segments);
  p.first_index = 1;
  return p;
}

TEST(RefineRegion, APslgMustBeOneClosedSimplePolygon) {
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  // In any order, either way round; a loose vertex is no part of it.
  const RefineRegion r = RefineRegion::polygon_of(ring_pslg(square, {{1, 2}, {0, 3}, {3, 2}, {0, 1}}));
  EXPECT_EQ(r.vertices().size(), 4u);
  EXPECT_TRUE(r.contains({0.5, 0.5}));
  EXPECT_TRUE(has(refusal([&] { RefineRegion::polygon_of(ring_pslg(square, {{0, 1}, {1, 2}, {2, 3}})); }),
                  "vertex 1 ends segment 1 only"));
  EXPECT_TRUE(has(refusal([&] {
                    RefineRegion::polygon_of(ring_pslg(square, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}}));
                  }),
                  "vertex 1 ends segment 1, segment 4 and segment 5"));
  const std::vector<Point> two{{0, 0}, {1, 0}, {0, 1}, {5, 5}, {6, 5}, {5, 6}};
  EXPECT_TRUE(has(refusal([&] {
                    RefineRegion::polygon_of(ring_pslg(two, {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}}));
                  }),
                  "more than one closed polygon"));
  const std::vector<Point> bow{{0, 0}, {2, 2}, {2, 0}, {0, 2}};
  EXPECT_TRUE(has(refusal([&] { RefineRegion::polygon_of(ring_pslg(bow, {{0, 1}, {1, 2}, {2, 3}, {3, 0}})); }),
                  "segment 1 and segment 3 touch or cross"));
}

// ---- Refinement in a region ----

// A 10 x 10 square with a vertex at every interior point of the unit lattice: its
// triangulation has triangles of area 0.5 everywhere, some with their centroid in any region
// below (a region inside one large triangle, its centroid elsewhere, refines nothing).
Pslg lattice_square() {
  Pslg in;
  in.points = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  for (std::uint32_t i = 0; i < 4; ++i) in.segments.push_back({i, (i + 1) % 4, 1});
  for (int x = 1; x < 10; ++x)
    for (int y = 1; y < 10; ++y) in.points.push_back({double(x), double(y)});
  return in;
}

Point centroid(const TriMesh& m, std::size_t t) {
  const Point &a = m.points[m.triangles[t][0]], &b = m.points[m.triangles[t][1]], &c = m.points[m.triangles[t][2]];
  return {(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
}

double area(const TriMesh& m, std::size_t t) {
  const Point &a = m.points[m.triangles[t][0]], &b = m.points[m.triangles[t][1]], &c = m.points[m.triangles[t][2]];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
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

struct RegionOutcome {
  std::size_t inside = 0;       // triangles with their centroid in the region
  std::size_t bad_inside = 0;   // of those, missing a bound
  std::size_t bad_outside = 0;  // triangles elsewhere missing a bound
};

// Counts, with this file's own measures, the triangles that miss an area bound (and a
// minimum angle, when > 0) in and out of the region.
RegionOutcome outcome(const TriMesh& m, const RefineRegion& region, double max_area, double min_angle) {
  RegionOutcome o;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const bool bad = area(m, t) > max_area * (1 + 1e-12) || (min_angle > 0.0 && min_angle_deg(m, t) < min_angle - 1e-9);
    if (region.contains(centroid(m, t))) {
      ++o.inside;
      o.bad_inside += bad;
    } else {
      o.bad_outside += bad;
    }
  }
  return o;
}

void expect_valid(const TriMesh& m, const Pslg* in, bool delaunay) {
  CheckOptions options;
  options.delaunay = delaunay;
  const CheckReport check = check_mesh(m, in, options);
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? std::string() : check.problems.front());
}

const RefineRegion& box_region() {
  static const RefineRegion r = RefineRegion::box({1, 1}, {3, 3});
  return r;
}
const RefineRegion& l_region() {  // an L of 1-wide arms along the bottom and left
  static const RefineRegion r = RefineRegion::polygon({{1, 1}, {5, 1}, {5, 2}, {2, 2}, {2, 5}, {1, 5}});
  return r;
}

// The lattice square at 25 degrees and an area of 0.02 in a box and in an L: met wherever the
// centroid is in the region, missed (by a wide margin) in the rest, on every data structure
// and insertion, which all make the same mesh.
TEST(RefineInRegion, DelaunayRefinementMeetsTheBoundsInTheRegionOnly) {
  const Pslg in = lattice_square();
  for (const RefineRegion* region : {&box_region(), &l_region()}) {
    SCOPED_TRACE(region->text());
    std::set<std::vector<std::array<std::uint32_t, 3>>> meshes;
    for (const TriangulateOptions& t : testing::all_configurations()) {
      SCOPED_TRACE(testing::describe(t));
      RefineOptions o;
      o.triangulate = t;
      o.criteria.min_angle_deg = 25;
      o.criteria.max_area = 0.02;
      o.region = *region;
      RefineReport report;
      const TriMesh m = refine(in, o, &report);
      expect_valid(m, &in, true);
      const RegionOutcome r = outcome(m, *region, 0.02, 25);
      EXPECT_GT(r.inside, 50u);
      EXPECT_EQ(r.bad_inside, 0u);
      EXPECT_GT(r.bad_outside, 20u);
      EXPECT_TRUE(report.bounds_met);  // the report speaks of the region
      EXPECT_EQ(report.bad_triangles, 0u);
      meshes.insert(canonical_triangles(m));
    }
    EXPECT_EQ(meshes.size(), 1u);
  }
}

// Lepp bisection (Rivara) under an area bound: its paths may leave the region, but the
// rest of the square stays coarse.
TEST(RefineInRegion, BisectionMeetsTheAreaBoundInTheRegionOnly) {
  const Pslg in = lattice_square();
  for (const RefineRegion* region : {&box_region(), &l_region()}) {
    SCOPED_TRACE(region->text());
    RefineOptions o;
    o.insertion = RefineInsertion::bisection;
    o.criteria.max_area = 0.02;
    o.region = *region;
    RefineReport report;
    const TriMesh m = refine(in, o, &report);
    expect_valid(m, &in, false);
    const RegionOutcome r = outcome(m, *region, 0.02, 0);
    EXPECT_GT(r.inside, 50u);
    EXPECT_EQ(r.bad_inside, 0u);
    EXPECT_GT(r.bad_outside, 20u);
    EXPECT_TRUE(report.bounds_met);
  }
}

// An existing mesh refined in part: the region meets the new bounds, and the old triangles
// well away from it come through as they were.
TEST(RefineInRegion, PartOfAnExistingMesh) {
  const Pslg in = lattice_square();
  RefineOptions first;
  first.criteria.min_angle_deg = 20;
  first.criteria.max_area = 2;
  const TriMesh old = refine(in, first);
  std::set<std::array<double, 6>> old_far;  // old triangles with every vertex 3 or more from the box
  const auto key = [](const TriMesh& m, std::size_t t) {
    std::array<Point, 3> p{m.points[m.triangles[t][0]], m.points[m.triangles[t][1]], m.points[m.triangles[t][2]]};
    std::sort(p.begin(), p.end(), lex_less);
    return std::array<double, 6>{p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y};
  };
  for (std::size_t t = 0; t < old.triangles.size(); ++t) {
    bool far = true;
    for (const std::uint32_t v : old.triangles[t]) {
      const Point& p = old.points[v];
      far = far && (p.x >= 6 || p.y >= 6);
    }
    if (far) old_far.insert(key(old, t));
  }
  ASSERT_GT(old_far.size(), 5u);
  for (const RefineRegion* region : {&box_region(), &l_region()}) {
    SCOPED_TRACE(region->text());
    for (const TriangulateOptions& t : testing::all_configurations()) {
      SCOPED_TRACE(testing::describe(t));
      RefineOptions o;
      o.triangulate = t;
      o.criteria.min_angle_deg = 25;
      o.criteria.max_area = 0.02;
      o.region = *region;
      RefineReport report;
      const TriMesh m = refine_mesh(old, o, &report);
      expect_valid(m, nullptr, true);
      const RegionOutcome r = outcome(m, *region, 0.02, 25);
      EXPECT_GT(r.inside, 50u);
      EXPECT_EQ(r.bad_inside, 0u);
      EXPECT_GT(r.bad_outside, 5u);
      std::size_t kept = 0;
      for (std::size_t f = 0; f < m.triangles.size(); ++f) kept += old_far.count(key(m, f));
      EXPECT_EQ(kept, old_far.size());
    }
  }
}

}  // namespace
}  // namespace meshstep
