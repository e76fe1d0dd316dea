// Surface bisection (surface/surface_refine.hpp) on surfaces made here: a subdivided
// icosahedron, a tetrahedron, a folded square patch, a long thin twisted strip, a torus
// (which the mesh structures can only hold cut open along seams), an open tube (two
// borders), two pieces in one list and two triangles touching at a vertex. On each: the
// output is a clean surface with the input's borders (no hanging vertex), the area and the
// border's length are kept, no angle falls below half the input's smallest, and every
// bound is met; the cap is respected and used; both data structures and two runs give the
// same surface; broken inputs are refused with what is wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/verify.hpp"
#include "meshstep/surface/surface_refine.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using io::Surface;
using surface::BisectionOptions;
using surface::BisectionReport;
using surface::bisect_surface;
using Triangle = std::array<std::uint32_t, 3>;

// ---------------------------------------------------------------------------------------
// Measures, written here again rather than taken from the library, so that a mistake there
// is not repeated in the check.

Point3 minus(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Point3 cross(const Point3& u, const Point3& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
double dot(const Point3& u, const Point3& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
double norm(const Point3& u) { return std::sqrt(dot(u, u)); }

double length(const Surface& s, std::uint32_t a, std::uint32_t b) {
  return norm(minus(s.vertices[b], s.vertices[a]));
}

double triangle_area(const Surface& s, const Triangle& t) {
  return 0.5 * norm(cross(minus(s.vertices[t[1]], s.vertices[t[0]]), minus(s.vertices[t[2]], s.vertices[t[0]])));
}

// In long double: a reference that owes nothing to the library's compensated sum.
long double total_area(const Surface& s) {
  long double sum = 0.0L;
  for (const Triangle& t : s.triangles) sum += triangle_area(s, t);
  return sum;
}

double smallest_angle_deg(const Surface& s) {
  double smallest = 180.0;
  for (const Triangle& t : s.triangles)
    for (int i = 0; i < 3; ++i) {
      const Point3 u = minus(s.vertices[t[(i + 1) % 3]], s.vertices[t[i]]);
      const Point3 v = minus(s.vertices[t[(i + 2) % 3]], s.vertices[t[i]]);
      smallest = std::min(smallest, std::atan2(norm(cross(u, v)), dot(u, v)) * 180.0 / std::numbers::pi);
    }
  return smallest;
}

double longest_edge(const Surface& s) {
  double longest = 0.0;
  for (const Triangle& t : s.triangles)
    for (int i = 0; i < 3; ++i) longest = std::max(longest, length(s, t[i], t[(i + 1) % 3]));
  return longest;
}

double largest_area(const Surface& s) {
  double largest = 0.0;
  for (const Triangle& t : s.triangles) largest = std::max(largest, triangle_area(s, t));
  return largest;
}

// Undirected edges and how many triangles use each.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses(const Surface& s) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const Triangle& t : s.triangles)
    for (int i = 0; i < 3; ++i) ++uses[std::minmax(t[i], t[(i + 1) % 3])];
  return uses;
}

long double border_length(const Surface& s) {
  long double sum = 0.0L;
  for (const auto& [edge, count] : edge_uses(s))
    if (count == 1) sum += length(s, edge.first, edge.second);
  return sum;
}

// ---------------------------------------------------------------------------------------
// Surfaces

// Turns every triangle of a convex closed surface round `center` to face outwards.
void face_outwards(Surface& s, const Point3& center) {
  for (Triangle& t : s.triangles) {
    const Point3 n = cross(minus(s.vertices[t[1]], s.vertices[t[0]]), minus(s.vertices[t[2]], s.vertices[t[0]]));
    if (dot(n, minus(s.vertices[t[0]], center)) < 0) std::swap(t[1], t[2]);
  }
}

Surface icosahedron() {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  Surface s;
  s.vertices = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  face_outwards(s, {0, 0, 0});
  return s;
}

// The icosahedron with every triangle cut into four `levels` times, its vertices pushed
// onto the unit sphere: a polyhedron of 20 * 4^levels flat triangles.
Surface icosphere(int levels) {
  Surface s = icosahedron();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    const auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto found = middle.find(key);
      if (found != middle.end()) return found->second;
      const Point3 &p = s.vertices[a], &q = s.vertices[b];
      s.vertices.push_back({(p.x + q.x) / 2, (p.y + q.y) / 2, (p.z + q.z) / 2});
      return middle[key] = static_cast<std::uint32_t>(s.vertices.size() - 1);
    };
    std::vector<Triangle> finer;
    for (const Triangle& t : s.triangles) {
      const std::uint32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.insert(finer.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
    }
    s.triangles = std::move(finer);
  }
  for (Point3& p : s.vertices) {
    const double r = norm(p);
    p = {p.x / r, p.y / r, p.z / r};
  }
  return s;
}

Surface tetrahedron() {
  Surface s;
  s.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  s.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  face_outwards(s, {0, 0, 0});
  return s;
}

// A quad (a, b, c, d), counterclockwise, as two triangles.
void add_quad(Surface& s, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  s.triangles.push_back({a, b, c});
  s.triangles.push_back({a, c, d});
}

// The unit square in n x n cells, folded along its middle column line into a roof.
Surface folded_square(int n = 6) {
  Surface s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      s.vertices.push_back({x, y, 0.8 * (0.5 - std::abs(x - 0.5))});
    }
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) add_quad(s, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return s;
}

// A ribbon 80 long and 1 wide, twisted along its length: triangles of 10 by 1, with
// angles under 6 degrees.
Surface thin_strip() {
  Surface s;
  const int n = 8;
  for (int i = 0; i <= n; ++i) {
    const double x = 10.0 * i, turn = 0.3 * i;
    s.vertices.push_back({x, 0.5 * std::cos(turn), 0.5 * std::sin(turn)});
    s.vertices.push_back({x, -0.5 * std::cos(turn), -0.5 * std::sin(turn)});
  }
  for (std::uint32_t i = 0; i < n; ++i) add_quad(s, 2 * i + 1, 2 * i + 3, 2 * i + 2, 2 * i);
  return s;
}

// A torus (radii 2 and 0.7) in m x n cells: genus 1, which the mesh structures can hold
// only cut open along seams.
Surface torus(int m = 12, int n = 8) {
  Surface s;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 2 * std::numbers::pi * i / m, v = 2 * std::numbers::pi * j / n;
      s.vertices.push_back({(2 + 0.7 * std::cos(v)) * std::cos(u), (2 + 0.7 * std::cos(v)) * std::sin(u),
                            0.7 * std::sin(v)});
    }
  const auto at = [m, n](int i, int j) { return static_cast<std::uint32_t>((i % m) * n + (j % n)); };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) add_quad(s, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return s;
}

// An open cylinder: two border loops.
Surface tube(int m = 10, int n = 4) {
  Surface s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i < m; ++i) {
      const double u = 2 * std::numbers::pi * i / m;
      s.vertices.push_back({std::cos(u), std::sin(u), 0.6 * j});
    }
  const auto at = [m](int i, int j) { return static_cast<std::uint32_t>(j * m + i % m); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i) add_quad(s, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return s;
}

// `b` moved by `shift` and appended to `a`: one list, two pieces.
Surface two_pieces(Surface a, const Surface& b, const Point3& shift) {
  const auto offset = static_cast<std::uint32_t>(a.vertices.size());
  for (const Point3& p : b.vertices) a.vertices.push_back({p.x + shift.x, p.y + shift.y, p.z + shift.z});
  for (const Triangle& t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return a;
}

// Two triangles sharing vertex 0 and nothing else: a pinched surface, manifold at every edge.
Surface bowtie() {
  Surface s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {-1, 0, 0.2}, {-1, -1, 0}};
  s.triangles = {{0, 1, 2}, {0, 3, 4}};
  return s;
}

struct Case {
  std::string name;
  Surface surface;
};

std::vector<Case> all_surfaces() {
  return {{"icosphere", icosphere(2)},
          {"tetrahedron", tetrahedron()},
          {"folded square", folded_square()},
          {"thin strip", thin_strip()},
          {"torus", torus()},
          {"tube", tube()},
          {"two pieces", two_pieces(tetrahedron(), icosphere(1), {5, 0, 0})},
          {"bowtie", bowtie()}};
}

// A bound that makes each surface several hundred times finer.
double fine_edge(const Surface& s) { return longest_edge(s) / 12.0; }

// Everything that must hold of any output: a clean surface with the input's borders, the
// input's vertices first and one more per bisection, the area and the border's length
// kept, no angle under half the input's smallest, and the report telling the truth.
void expect_sound(const Surface& in, const Surface& out, const BisectionReport& r, const std::string& name) {
  SCOPED_TRACE(name);
  const io::SurfaceReport before = io::report_surface(in), after = io::report_surface(out);
  EXPECT_TRUE(after.clean()) << io::describe(after);
  EXPECT_EQ(after.boundary_loops, before.boundary_loops);
  EXPECT_EQ(after.boundary_edges == 0, before.boundary_edges == 0);
  for (const auto& [edge, count] : edge_uses(out)) ASSERT_LE(count, 2);

  ASSERT_EQ(out.vertices.size(), in.vertices.size() + r.bisections);
  for (std::size_t v = 0; v < in.vertices.size(); ++v) ASSERT_EQ(out.vertices[v], in.vertices[v]);
  EXPECT_EQ(out.triangles.size(), r.triangles);
  // Each bisection adds one triangle on a border and two elsewhere.
  EXPECT_GE(out.triangles.size(), in.triangles.size() + r.bisections);
  EXPECT_LE(out.triangles.size(), in.triangles.size() + 2 * r.bisections);

  const long double area_in = total_area(in), area_out = total_area(out);
  EXPECT_LE(std::abs(area_out - area_in), 1e-12L * area_in);
  EXPECT_NEAR(r.area_before, static_cast<double>(area_in), 1e-12 * r.area_before);
  EXPECT_NEAR(r.area_after, static_cast<double>(area_out), 1e-12 * r.area_after);
  const long double border_in = border_length(in);
  EXPECT_LE(std::abs(border_length(out) - border_in), 1e-12L * border_in);

  const double angle_in = smallest_angle_deg(in), angle_out = smallest_angle_deg(out);
  EXPECT_GE(angle_out, angle_in / 2.0);
  EXPECT_NEAR(r.smallest_angle_before_deg, angle_in, 1e-9);
  EXPECT_NEAR(r.smallest_angle_after_deg, angle_out, 1e-9);
}

std::string refusal(const Surface& s, const BisectionOptions& options = {}) {
  try {
    bisect_surface(s, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

// ---------------------------------------------------------------------------------------

// Coordinates of 1e300 (or all of 1e-300) made every area infinite (or zero): the surface
// came back unrefined, silently. Refused, naming the vertex.
TEST(SurfaceBisection, CoordinatesBeyondWhatDoublesMeasureAreRefused) {
  BisectionOptions options;
  options.max_edge = 0.3;
  for (const double scale : {1e300, 1e-300}) {
    Surface s = folded_square(2);
    for (auto& p : s.vertices) p = {p.x * scale, p.y * scale, p.z * scale};
    options.max_edge = 0.3 * scale;
    const std::string why = refusal(s, options);
    EXPECT_NE(why.find("measured in doubles"), std::string::npos) << scale << ": " << why;
  }
  // Within the range, the same surface is refined as at unit size.
  Surface s = folded_square(2);
  for (auto& p : s.vertices) p = {p.x * 0x1p200, p.y * 0x1p200, p.z * 0x1p200};
  options.max_edge = 0.3 * 0x1p200;
  EXPECT_GT(bisect_surface(s, options).triangles.size(), folded_square(2).triangles.size());
}

TEST(SurfaceBisection, ACutThatDoublesCannotMakeIsRefusedAndCounted) {
  // A tetrahedron with one corner at 4.4e27 beside corners a unit apart: the midpoints of
  // its two long edges from 0 and from 1 round to the same point, so cutting both would
  // make degenerate triangles. The run leaves what it cannot cut and says so.
  Surface s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {4.4e27, 1, 0}, {0, 0, 1}};
  s.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  BisectionOptions options;
  options.max_edge = 1e27;
  for (const DataStructure ds : {DataStructure::tds, DataStructure::dcel}) {
    options.data_structure = ds;
    BisectionReport r;
    const Surface out = bisect_surface(s, options, &r);
    const io::SurfaceReport clean = io::report_surface(out);
    EXPECT_EQ(clean.degenerate_triangles, 0u) << io::describe(clean);
    EXPECT_TRUE(clean.clean()) << io::describe(clean);
    EXPECT_EQ(clean.boundary_edges, 0u);
    EXPECT_FALSE(r.capped);
    EXPECT_GT(r.too_fine_to_cut, 0u);
    EXPECT_GT(r.over_bounds, 0u);
    EXPECT_GT(r.bisections, 0u);  // the cuts it could make, it made
  }
}

TEST(SurfaceBisection, EdgeBoundMetOnEverySurfaceWithoutHangingVertices) {
  for (const Case& c : all_surfaces()) {
    BisectionOptions options;
    options.max_edge = fine_edge(c.surface);
    BisectionReport r;
    const Surface out = bisect_surface(c.surface, options, &r);
    expect_sound(c.surface, out, r, c.name);
    EXPECT_GT(r.bisections, 20u) << c.name;
    EXPECT_LE(longest_edge(out), options.max_edge) << c.name;
    EXPECT_FALSE(r.capped) << c.name;
  }
}

TEST(SurfaceBisection, AreaBoundMetOnEverySurface) {
  for (const Case& c : all_surfaces()) {
    BisectionOptions options;
    options.max_area = largest_area(c.surface) / 50.0;
    BisectionReport r;
    const Surface out = bisect_surface(c.surface, options, &r);
    expect_sound(c.surface, out, r, c.name);
    EXPECT_GT(r.bisections, 0u) << c.name;
    EXPECT_LE(largest_area(out), options.max_area) << c.name;
  }
}

// The bisection keeps the polyhedron's area, not the sphere's it approximates: the
// midpoints stay on the flat faces.
TEST(SurfaceBisection, SubdividedIcosahedronKeepsItsAreaNotTheSpheres) {
  const Surface in = icosphere(1);
  BisectionOptions options;
  options.max_edge = 0.05;
  BisectionReport r;
  const Surface out = bisect_surface(in, options, &r);
  EXPECT_GT(r.triangles, 10000u);
  EXPECT_LE(std::abs(r.area_after - r.area_before), 1e-12 * r.area_before);
  EXPECT_LT(r.area_after, 4 * std::numbers::pi - 0.1);  // well inside the sphere
  // Every new vertex lies inside the unit sphere, none was pushed out onto it.
  for (std::size_t v = in.vertices.size(); v < out.vertices.size(); ++v)
    ASSERT_LT(norm(out.vertices[v]), 1.0 - 1e-6);
}

TEST(SurfaceBisection, BothBoundsTogether) {
  const Surface in = thin_strip();
  BisectionOptions options;
  options.max_edge = 4.0;  // the long sides
  options.max_area = 0.5;  // and the cells' area, reached only by also cutting across
  BisectionReport r;
  const Surface out = bisect_surface(in, options, &r);
  expect_sound(in, out, r, "thin strip");
  EXPECT_LE(longest_edge(out), options.max_edge);
  EXPECT_LE(largest_area(out), options.max_area);
}

TEST(SurfaceBisection, NothingToDoGivesTheInputBack) {
  const Surface in = torus();
  BisectionOptions options;
  options.max_edge = 2 * longest_edge(in);
  BisectionReport r;
  const Surface out = bisect_surface(in, options, &r);
  EXPECT_EQ(r.bisections, 0u);
  EXPECT_EQ(out.vertices, in.vertices);
  // The same triangles, each from its smallest vertex, sorted.
  std::vector<Triangle> expected;
  for (const Triangle& t : in.triangles) {
    Triangle u = t;
    while (u[0] > u[1] || u[0] > u[2]) u = {u[1], u[2], u[0]};
    expected.push_back(u);
  }
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(out.triangles, expected);
  // No bound at all: nothing to do either.
  EXPECT_EQ(bisect_surface(in, {}).triangles, expected);
  // No triangles: the vertices come back as they were.
  Surface empty;
  empty.vertices = {{1, 2, 3}};
  options.max_edge = 0.1;
  const Surface none = bisect_surface(empty, options, &r);
  EXPECT_EQ(none.vertices, empty.vertices);
  EXPECT_TRUE(none.triangles.empty());
  EXPECT_EQ(r.bisections, 0u);
}

TEST(SurfaceBisection, CapIsRespectedAndUsed) {
  for (const Case& c : all_surfaces()) {
    BisectionOptions options;
    options.max_edge = fine_edge(c.surface);
    options.max_triangles = c.surface.triangles.size() + 101;
    BisectionReport r;
    const Surface out = bisect_surface(c.surface, options, &r);
    expect_sound(c.surface, out, r, c.name);
    EXPECT_TRUE(r.capped) << c.name;
    EXPECT_LE(out.triangles.size(), options.max_triangles) << c.name;
    // A bisection adds at most two triangles: the run stops only when the next would pass.
    EXPECT_GE(out.triangles.size() + 2, options.max_triangles + 1) << c.name;
    EXPECT_GT(longest_edge(out), options.max_edge) << c.name;
  }
  // A cap below the input's size: nothing is cut.
  BisectionOptions options;
  options.max_edge = 0.1;
  options.max_triangles = 3;
  BisectionReport r;
  EXPECT_EQ(bisect_surface(tetrahedron(), options, &r).triangles.size(), 4u);
  EXPECT_TRUE(r.capped);
  EXPECT_EQ(r.bisections, 0u);
}

TEST(SurfaceBisection, TdsAndDcelGiveTheSameSurface) {
  for (const Case& c : all_surfaces()) {
    BisectionOptions options;
    options.max_edge = fine_edge(c.surface);
    options.max_area = largest_area(c.surface) / 300.0;
    options.data_structure = DataStructure::tds;
    BisectionReport rt, rd;
    const Surface tds = bisect_surface(c.surface, options, &rt);
    options.data_structure = DataStructure::dcel;
    const Surface dcel = bisect_surface(c.surface, options, &rd);
    EXPECT_GT(rt.bisections, 0u) << c.name;
    EXPECT_EQ(tds.vertices, dcel.vertices) << c.name;
    EXPECT_EQ(tds.triangles, dcel.triangles) << c.name;
    EXPECT_EQ(rt.smallest_angle_after_deg, rd.smallest_angle_after_deg) << c.name;
    // Capped halfway, too: the order of the cuts is the same, not only their end.
    options.max_triangles = (c.surface.triangles.size() + tds.triangles.size()) / 2;
    options.data_structure = DataStructure::tds;
    const Surface tds_capped = bisect_surface(c.surface, options);
    options.data_structure = DataStructure::dcel;
    EXPECT_EQ(tds_capped.triangles, bisect_surface(c.surface, options).triangles) << c.name;
  }
}

TEST(SurfaceBisection, TwoRunsGiveTheSameSurface) {
  for (const Case& c : all_surfaces()) {
    BisectionOptions options;
    options.max_area = largest_area(c.surface) / 100.0;
    const Surface first = bisect_surface(c.surface, options), second = bisect_surface(c.surface, options);
    EXPECT_EQ(first.vertices, second.vertices) << c.name;
    EXPECT_EQ(first.triangles, second.triangles) << c.name;
  }
}

// Largest first: with a cap, the run has spent its triangles on the worst offenders, so
// what is left over the bound is no worse than what a larger cap would leave.
TEST(SurfaceBisection, LargestTrianglesAreCutFirst) {
  Surface in = folded_square(4);
  // The cell at the far corner, last in the list, made much larger than the rest: a run
  // in list order would spend a small cap on the small cells first.
  in.vertices.back() = {4.0, 4.0, 0.0};
  const double big = largest_area(in);
  BisectionOptions options;
  options.max_area = big / 40.0;
  double previous = big;
  for (const std::size_t cap : {36u, 80u, 160u, 320u}) {
    options.max_triangles = cap;
    const double largest = largest_area(bisect_surface(in, options));
    EXPECT_LE(largest, previous) << cap;
    previous = largest;
  }
  // Four triangles more than the input's 32 already went to the big corner: its two
  // triangles are cut in two, and no triangle is as large as half the biggest any more.
  options.max_triangles = 36;
  EXPECT_LE(largest_area(bisect_surface(in, options)), big / 2.0 * (1 + 1e-12));
}

// A square bent along its diagonal: the diagonal is the longest edge of both triangles, so
// one bisection cuts both at its midpoint, exactly.
TEST(SurfaceBisection, CutsTheLongestEdgeAtItsMidpoint) {
  Surface bent;
  bent.vertices = {{0, 0, 0}, {2, 0, 0.5}, {2, 2, 0}, {0, 2, 0.5}};
  bent.triangles = {{0, 1, 2}, {0, 2, 3}};
  BisectionOptions options;
  options.max_edge = 2.5;  // over the sides (about 2.06), under the diagonal (about 2.83)
  BisectionReport r;
  const Surface out = bisect_surface(bent, options, &r);
  EXPECT_EQ(r.bisections, 1u);
  ASSERT_EQ(out.vertices.size(), 5u);
  EXPECT_EQ(out.vertices[4], (Point3{1, 1, 0}));
  const std::vector<Triangle> expected = {{0, 1, 4}, {0, 4, 3}, {1, 2, 4}, {2, 3, 4}};
  EXPECT_EQ(out.triangles, expected);
}

// Lepp: the target's longest edge is shorter than the longest edge of the triangle across
// it, so that neighbour is cut first, across its own longest edge (on the border).
TEST(SurfaceBisection, FollowsTheLongestEdgePathToItsEnd) {
  Surface s;
  // Target (0, 1, 2): large, longest edge 0-1 (length 4). Neighbour (1, 0, 3): thin and
  // small, longest edge 1-3 (about 5.1), on the border.
  s.vertices = {{0, 0, 0}, {4, 0, 0}, {2, 3, 1}, {-1, -0.2, 0}};
  s.triangles = {{0, 1, 2}, {1, 0, 3}};
  const double target_area = triangle_area(s, s.triangles[0]);
  ASSERT_GT(target_area, 10 * triangle_area(s, s.triangles[1]));
  BisectionOptions options;
  options.max_area = target_area * 0.9;  // only the target is over it
  options.max_triangles = 3;             // room for one bisection
  BisectionReport r;
  const Surface out = bisect_surface(s, options, &r);
  ASSERT_EQ(r.bisections, 1u);
  EXPECT_TRUE(r.capped);  // the target itself is not cut yet
  EXPECT_EQ(out.vertices[4], (Point3{1.5, -0.1, 0}));  // midpoint of 1-3, not of 0-1
  // Without the cap the target is cut too, and the bound met.
  options.max_triangles = 0;
  const Surface done = bisect_surface(s, options, &r);
  EXPECT_FALSE(r.capped);
  EXPECT_LE(largest_area(done), options.max_area);
  expect_sound(s, done, r, "lepp");
}

TEST(SurfaceBisection, RefusesWhatIsNoManifoldSurface) {
  // Three triangles on the edge 0-1.
  Surface fin;
  fin.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}};
  EXPECT_NE(refusal(fin).find("non-manifold edge"), std::string::npos) << refusal(fin);

  Surface turned = tetrahedron();
  std::swap(turned.triangles[0][1], turned.triangles[0][2]);
  EXPECT_NE(refusal(turned).find("opposite orientation"), std::string::npos) << refusal(turned);

  Surface flat = tetrahedron();
  flat.vertices.push_back({2, 2, 2});
  flat.vertices.push_back({3, 3, 3});
  flat.triangles.push_back({0, 4, 5});  // (1,1,1), (2,2,2), (3,3,3): collinear
  EXPECT_NE(refusal(flat).find("degenerate triangle"), std::string::npos) << refusal(flat);

  Surface repeated = tetrahedron();
  repeated.triangles.push_back({0, 0, 1});
  EXPECT_NE(refusal(repeated).find("degenerate triangle"), std::string::npos) << refusal(repeated);

  Surface twice = tetrahedron();
  twice.triangles.push_back(twice.triangles[0]);
  EXPECT_NE(refusal(twice).find("manifold"), std::string::npos) << refusal(twice);

  Surface past_end = tetrahedron();
  past_end.triangles[0][0] = 9;
  EXPECT_NE(refusal(past_end).find("vertex 9"), std::string::npos) << refusal(past_end);

  Surface not_finite = tetrahedron();
  not_finite.vertices[2].y = std::nan("");
  EXPECT_NE(refusal(not_finite).find("vertex 2 has a coordinate that is not finite"), std::string::npos)
      << refusal(not_finite);

  BisectionOptions negative;
  negative.max_edge = -1.0;
  EXPECT_NE(refusal(tetrahedron(), negative).find("edge length must be"), std::string::npos);

  // Vertices of no triangle are no problem: they are kept where they are.
  Surface spare = tetrahedron();
  spare.vertices.push_back({7, 7, 7});
  BisectionOptions options;
  options.max_edge = 1.0;
  const Surface out = bisect_surface(spare, options);
  EXPECT_EQ(out.vertices[4], (Point3{7, 7, 7}));
  EXPECT_EQ(io::report_surface(out).unused_vertices, 1u);
}

}  // namespace
}  // namespace meshstep

namespace meshstep {
namespace {

// ---------------------------------------------------------------------------------------
// Recorded runs (BisectionOptions::record): the bisection and the flips after it, on every
// surface and both data structures. The log replays, forward and backward, to the surface
// the run returned; every vertex carries its 3D position (x, y in the plane, z as an
// elevation); a step per target and per flip; and recording changes nothing.

struct Replayed {
  std::vector<Triangle> triangles;  // each from its smallest vertex id, sorted
  std::vector<Point3> vertices;
};

Replayed replay_to_end(const replay::LogReader& log) {
  replay::Replay cursor(log);
  cursor.seek_event(log.event_count());
  Replayed out;
  for (const replay::FaceRecord& r : cursor.slots()) {
    if (r.dead() || r.ghost()) continue;
    Triangle t = r.v;
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
    out.triangles.push_back(t);
  }
  std::sort(out.triangles.begin(), out.triangles.end());
  for (const replay::VertexInfo& v : log.vertices()) out.vertices.push_back({v.point.x, v.point.y, v.z});
  return out;
}

TEST(SurfaceRecord, EveryRunReplaysToItsSurfaceOnBothStructures) {
  testing::TempDir dir;
  for (const Case& c : all_surfaces()) {
    std::vector<Triangle> first;
    for (const DataStructure ds : {DataStructure::tds, DataStructure::dcel}) {
      SCOPED_TRACE(c.name + (ds == DataStructure::dcel ? " dcel" : " tds"));
      BisectionOptions options;
      options.max_edge = fine_edge(c.surface);
      options.flip_dihedral_deg = 20.0;
      options.data_structure = ds;
      BisectionReport plain_report, report;
      const Surface plain = bisect_surface(c.surface, options, &plain_report);

      const std::string path = dir.file("run.mslog");
      replay::LogHeader header;
      header.algorithm = "lepp-bisection";
      header.parameters = "input_vertices=" + std::to_string(c.surface.vertices.size());
      replay::LogWriterOptions small_blocks;
      small_blocks.block_bytes = 4096;
      small_blocks.keyframes.min_events = 256;
      {
        replay::LogWriter writer(path, header, small_blocks);
        options.record = &writer;
        const Surface out = bisect_surface(c.surface, options, &report);
        writer.finish();
        EXPECT_EQ(out.vertices, plain.vertices);
        EXPECT_EQ(out.triangles, plain.triangles);
        EXPECT_EQ(report.flips, plain_report.flips);
      }
      const replay::LogReader log(path);
      ASSERT_TRUE(log.complete());
      EXPECT_TRUE(log.has_elevation());
      const replay::VerifyReport verified = replay::verify(log);
      EXPECT_TRUE(verified.ok) << verified.problem;

      const Replayed end = replay_to_end(log);
      EXPECT_EQ(end.triangles, plain.triangles);
      EXPECT_EQ(end.vertices, plain.vertices);

      std::size_t bisect_steps = 0, flip_steps = 0, bisections = 0;
      for (std::uint64_t k = 0; k < log.step_count(); ++k) {
        bisect_steps += log.step_kind(k) == replay::StepKind::bisect;
        flip_steps += log.step_kind(k) == replay::StepKind::flip_3d;
      }
      for (std::uint64_t e = 0; e < log.event_count(); ++e) {
        const replay::Event ev = log.event(e);
        bisections += ev.type == replay::EventType::vertex && ev.ids[0] >= c.surface.vertices.size();
      }
      EXPECT_EQ(bisections, report.bisections);
      EXPECT_GT(bisect_steps, 0u);
      EXPECT_LE(bisect_steps, report.bisections);
      EXPECT_EQ(flip_steps, report.flips);
      if (first.empty()) first = plain.triangles;
      else EXPECT_EQ(plain.triangles, first) << "tds and dcel differ after the flips";
    }
  }
}

}  // namespace
}  // namespace meshstep
