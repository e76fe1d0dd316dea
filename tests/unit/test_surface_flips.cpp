// Edge flips on 3D surfaces (surface/surface_flips.hpp), on surfaces made here: a thin
// rhombus in a plane, the same rhombus folded, a dart whose flip would fold it over, a
// closed tetrahedron, and a bumpy grid with the worse diagonal in every cell. Checked with
// measures written again here: which pairs flip, that the surface stays clean with its area
// (coplanar flips) or within the dihedral bound (others), that its smallest angle never
// falls, and that the order of the triangle list does not matter. After a bisection, the
// flips keep its size bounds (issue 31): two flat quadrilaterals whose flips would make a
// triangle over the area or the edge bound, and the bumpy grid with a dihedral bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/surface/surface_flips.hpp"
#include "meshstep/surface/surface_refine.hpp"

namespace meshstep {
namespace {

using io::Surface;
using surface::FlipOptions;
using surface::FlipReport;
using surface::flip_surface;
using Triangle = std::array<std::uint32_t, 3>;

double length(const Point3& u) { return std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z); }
Point3 minus(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Point3 cross(const Point3& u, const Point3& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
double angle_deg(const Point3& o, const Point3& p, const Point3& q) {
  const Point3 u = minus(p, o), v = minus(q, o);
  return std::atan2(length(cross(u, v)), u.x * v.x + u.y * v.y + u.z * v.z) * 180.0 / std::numbers::pi;
}
double smallest_angle(const Surface& s) {
  double m = 180.0;
  for (const Triangle& t : s.triangles)
    for (int k = 0; k < 3; ++k)
      m = std::min(m, angle_deg(s.vertices[t[k]], s.vertices[t[(k + 1) % 3]], s.vertices[t[(k + 2) % 3]]));
  return m;
}
double area(const Surface& s) {
  double sum = 0.0;
  for (const Triangle& t : s.triangles)
    sum += 0.5 * length(cross(minus(s.vertices[t[1]], s.vertices[t[0]]), minus(s.vertices[t[2]], s.vertices[t[0]])));
  return sum;
}
bool has_edge(const Surface& s, std::uint32_t a, std::uint32_t b) {
  for (const Triangle& t : s.triangles)
    for (int k = 0; k < 3; ++k)
      if ((t[k] == a && t[(k + 1) % 3] == b) || (t[k] == b && t[(k + 1) % 3] == a)) return true;
  return false;
}

// a(-2,0) b(2,0) c(0,0.5,h) d(0,-0.5): abc and bad share the long edge ab.
Surface rhombus(double c_height = 0.0) {
  Surface s;
  s.vertices = {{-2, 0, 0}, {2, 0, 0}, {0, 0.5, c_height}, {0, -0.5, 0}};
  s.triangles = {{0, 1, 2}, {1, 0, 3}};
  return s;
}

TEST(SurfaceFlips, ACoplanarThinPairFlipsToItsOtherDiagonalKeepingTheArea) {
  const Surface in = rhombus();
  FlipReport report;
  const Surface out = flip_surface(in, FlipOptions{0.0}, &report);
  EXPECT_EQ(report.flips, 1u);
  EXPECT_TRUE(has_edge(out, 2, 3));
  EXPECT_FALSE(has_edge(out, 0, 1));
  EXPECT_GT(smallest_angle(out), smallest_angle(in) + 10.0);
  EXPECT_NEAR(area(out), area(in), 1e-12 * area(in));
  EXPECT_TRUE(io::report_surface(out).clean());
  EXPECT_DOUBLE_EQ(report.smallest_angle_after_deg, smallest_angle(out));
  // Flipped once, it stays: the other diagonal is the better one now.
  EXPECT_EQ(flip_surface(out, FlipOptions{180.0}).triangles, out.triangles);
}

TEST(SurfaceFlips, AFoldedPairFlipsOnlyUnderABoundAboveItsDihedralAngle) {
  const Surface in = rhombus(0.5);
  const Point3 n1 = cross(minus(in.vertices[1], in.vertices[0]), minus(in.vertices[2], in.vertices[0]));
  const Point3 n2 = cross(minus(in.vertices[0], in.vertices[1]), minus(in.vertices[3], in.vertices[1]));
  const double dihedral =
      std::atan2(length(cross(n1, n2)), n1.x * n2.x + n1.y * n2.y + n1.z * n2.z) * 180.0 / std::numbers::pi;
  ASSERT_GT(dihedral, 20.0);
  FlipReport below, above;
  EXPECT_EQ(flip_surface(in, FlipOptions{dihedral - 1.0}, &below).triangles.size(), 2u);
  EXPECT_EQ(below.flips, 0u);
  const Surface out = flip_surface(in, FlipOptions{dihedral + 1.0}, &above);
  EXPECT_EQ(above.flips, 1u);
  EXPECT_NEAR(above.largest_dihedral_flipped_deg, dihedral, 1e-9);
  EXPECT_TRUE(has_edge(out, 2, 3));
}

TEST(SurfaceFlips, NeverFoldsAPairOverNorJoinsTwoVerticesTwice) {
  // A dart: the diagonal cd would pass outside the pair, so the new triangles would face
  // away; its angles are no reason.
  Surface dart;
  dart.vertices = {{0, 0, 0}, {4, 0, 0}, {-1, 1, 0}, {-1, -0.1, 0}};
  dart.triangles = {{0, 1, 2}, {1, 0, 3}};
  FlipReport report;
  const Surface out = flip_surface(dart, FlipOptions{180.0}, &report);
  EXPECT_EQ(report.flips, 0u);
  EXPECT_TRUE(has_edge(out, 0, 1));
  // A closed tetrahedron: every flip would join two vertices joined already.
  Surface tet;
  tet.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  FlipReport t;
  const Surface same = flip_surface(tet, FlipOptions{180.0}, &t);
  EXPECT_EQ(t.flips, 0u);
  EXPECT_TRUE(io::report_surface(same).clean());
  EXPECT_EQ(io::report_surface(same).boundary_edges, 0u);
}

// A 12 x 12 grid of bumps, each cell cut along the diagonal that makes the thinner pair.
Surface bumpy_grid(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  Surface s;
  const int n = 12;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.vertices.push_back({i * 1.0 + (j % 2) * 0.45, j * 0.35, u(rng)});
  const auto id = [&](int i, int j) { return static_cast<std::uint32_t>(i + j * (n + 1)); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

TEST(SurfaceFlips, OnABumpyGridRaisesTheSmallestAngleAndStaysWithinTheBound) {
  const Surface in = bumpy_grid(7);
  for (const double bound : {0.5, 3.0, 10.0}) {
    SCOPED_TRACE(bound);
    FlipReport report;
    const Surface out = flip_surface(in, FlipOptions{bound}, &report);
    EXPECT_GT(report.flips, 0u);
    EXPECT_LE(report.largest_dihedral_flipped_deg, bound);
    EXPECT_EQ(out.triangles.size(), in.triangles.size());
    EXPECT_EQ(out.vertices, in.vertices);
    const io::SurfaceReport r = io::report_surface(out);
    EXPECT_TRUE(r.clean()) << io::describe(r);
    EXPECT_EQ(r.boundary_loops, 1u);
    EXPECT_GE(smallest_angle(out), smallest_angle(in) - 1e-12);
    // A flip lifts a vertex pair by at most the bump heights: the area hardly moves.
    EXPECT_NEAR(area(out), area(in), 1e-3 * area(in));
  }
  // The order of the list and of each triangle's corners does not matter.
  Surface shuffled = in;
  std::mt19937 rng(3);
  std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end(), rng);
  for (Triangle& t : shuffled.triangles) std::rotate(t.begin(), t.begin() + (rng() % 3), t.end());
  EXPECT_EQ(flip_surface(shuffled, FlipOptions{3.0}).triangles, flip_surface(in, FlipOptions{3.0}).triangles);
}

TEST(SurfaceFlips, RefusesABadBoundAndABrokenSurface) {
  EXPECT_THROW(flip_surface(rhombus(), FlipOptions{-1.0}), InputError);
  EXPECT_THROW(flip_surface(rhombus(), FlipOptions{181.0}), InputError);
  EXPECT_THROW(flip_surface(rhombus(), FlipOptions{std::nan("")}), InputError);
  Surface flipped_neighbour = rhombus();
  flipped_neighbour.triangles[1] = {0, 1, 3};  // the shared edge twice in one direction
  EXPECT_THROW(flip_surface(flipped_neighbour, FlipOptions{1.0}), InputError);
  Surface nan = rhombus();
  nan.vertices[2].z = std::nan("");
  EXPECT_THROW(flip_surface(nan, FlipOptions{1.0}), InputError);
}

// Bisection to size bounds, then flips in the same mesh (surface_refine.hpp).
double triangle_area(const Surface& s, const Triangle& t) {
  return 0.5 * length(cross(minus(s.vertices[t[1]], s.vertices[t[0]]), minus(s.vertices[t[2]], s.vertices[t[0]])));
}
double longest_edge(const Surface& s, const Triangle& t) {
  double l = 0.0;
  for (int k = 0; k < 3; ++k) l = std::max(l, length(minus(s.vertices[t[(k + 1) % 3]], s.vertices[t[k]])));
  return l;
}
std::size_t over_area(const Surface& s, double max_area) {
  return static_cast<std::size_t>(std::count_if(s.triangles.begin(), s.triangles.end(),
                                                [&](const Triangle& t) { return triangle_area(s, t) > max_area; }));
}
std::size_t over_edge(const Surface& s, double max_edge) {
  return static_cast<std::size_t>(std::count_if(s.triangles.begin(), s.triangles.end(),
                                                [&](const Triangle& t) { return longest_edge(s, t) > max_edge; }));
}

// A flat quadrilateral in two triangles: bisected to an area of 0.3, its four triangles hold
// a coplanar pair whose flip (for a larger smallest angle) moves area into one of them, to
// 1.18 times the bound.
Surface flat_quadrilateral() {
  Surface s;
  s.vertices = {{0.18, 0.19, 0}, {0.99, -0.14, 0}, {-0.3, 1.1, 0}, {0.98, 1.16, 0}};
  s.triangles = {{0, 1, 3}, {0, 3, 2}};
  return s;
}

// A flat 2 x 2 grid, its nodes moved: bisected to edges of 0.8, two of its coplanar pairs
// would flip to a diagonal longer than that.
Surface flat_jittered_grid() {
  Surface s;
  s.vertices = {{0.09, 0.17, 0}, {1.21, 0.31, 0}, {2.17, 0.3, 0},  {-0.33, 0.98, 0}, {1.31, 1.1, 0},
                {2.28, 0.73, 0}, {-0.02, 1.82, 0}, {1.03, 2.05, 0}, {1.66, 1.8, 0}};
  s.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {3, 4, 7}, {3, 7, 6}, {4, 5, 8}, {4, 8, 7}};
  return s;
}

surface::BisectionOptions bounds_then_flips(double max_edge, double max_area, double dihedral, DataStructure ds) {
  surface::BisectionOptions o;
  o.max_edge = max_edge;
  o.max_area = max_area;
  o.flip_dihedral_deg = dihedral;
  o.data_structure = ds;
  return o;
}

TEST(SurfaceFlipsAfterBisection, KeepTheAreaBoundOnBothMeshStructures) {
  struct Case {
    const char* name;
    Surface in;
    double max_area, dihedral;
    bool some_flip;  // whether a flip keeps the bound (the quadrilateral's only one does not)
  };
  const Case cases[] = {{"flat quadrilateral", flat_quadrilateral(), 0.3, 0.0, false},
                        {"flat quadrilateral, finer", flat_quadrilateral(), 0.08, 0.0, true},
                        {"bumpy grid", bumpy_grid(7), 0.011, 10.0, true}};
  for (const Case& c : cases)
    for (const DataStructure ds : {DataStructure::tds, DataStructure::dcel}) {
      SCOPED_TRACE(std::string(c.name) + (ds == DataStructure::tds ? " on the tds" : " on the dcel"));
      surface::BisectionReport report;
      const Surface out = surface::bisect_surface(c.in, bounds_then_flips(0.0, c.max_area, c.dihedral, ds), &report);
      EXPECT_EQ(report.flips > 0, c.some_flip);
      EXPECT_EQ(over_area(out, c.max_area), 0u);
      EXPECT_EQ(report.over_bounds, 0u);
      EXPECT_TRUE(io::report_surface(out).clean());
    }
}

TEST(SurfaceFlipsAfterBisection, KeepTheEdgeBoundOnBothMeshStructures) {
  for (const DataStructure ds : {DataStructure::tds, DataStructure::dcel}) {
    surface::BisectionReport report;
    const Surface out = surface::bisect_surface(flat_jittered_grid(), bounds_then_flips(0.8, 0.0, 0.0, ds), &report);
    EXPECT_GT(report.flips, 0u);
    EXPECT_EQ(over_edge(out, 0.8), 0u);
    EXPECT_EQ(report.over_bounds, 0u);
    EXPECT_GE(smallest_angle(out), report.smallest_angle_before_deg / 2.0 - 1e-9);
  }
}

// Stopped by a cap, the run ends with triangles over the bound: the report counts them, and
// the flips made no more of them than the bisection left.
TEST(SurfaceFlipsAfterBisection, UnderACapCountTheTrianglesOverTheBoundsAndAddNone) {
  for (const std::size_t cap : {14u, 18u, 26u, 30u}) {
    SCOPED_TRACE(cap);
    surface::BisectionOptions flipped = bounds_then_flips(0.8, 0.1, 0.0, DataStructure::tds);
    flipped.max_triangles = cap;
    surface::BisectionOptions unflipped = flipped;
    unflipped.flip_dihedral_deg = -1.0;
    surface::BisectionReport with, without;
    const Surface a = surface::bisect_surface(flat_jittered_grid(), flipped, &with);
    const Surface b = surface::bisect_surface(flat_jittered_grid(), unflipped, &without);
    EXPECT_TRUE(with.capped);
    EXPECT_EQ(with.over_max_edge, over_edge(a, 0.8));
    EXPECT_EQ(with.over_max_area, over_area(a, 0.1));
    EXPECT_GT(with.over_bounds, 0u);
    EXPECT_GE(with.over_bounds, std::max(with.over_max_edge, with.over_max_area));
    EXPECT_LE(with.over_bounds, with.over_max_edge + with.over_max_area);
    EXPECT_EQ(without.over_max_edge, over_edge(b, 0.8));
    EXPECT_LE(with.over_bounds, without.over_bounds);
  }
}

}  // namespace
}  // namespace meshstep
