// Tests of the mesh checker: valid hand-built meshes pass, and each kind of defect is both
// detected and named in the report.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>

#include "meshstep/check/mesh_check.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep {
namespace {

using Tri = std::array<std::uint32_t, 3>;

TriMesh make_mesh(std::vector<Point> points, std::vector<Tri> triangles,
                  std::vector<Segment> segments = {}) {
  TriMesh mesh;
  mesh.points = std::move(points);
  mesh.triangles = std::move(triangles);
  mesh.segments = std::move(segments);
  mesh.input_vertex_count = mesh.points.size();
  return mesh;
}

// Neighbors computed the slow, obvious way, to give the checker a correct list to accept.
std::vector<Tri> brute_force_neighbors(const TriMesh& mesh) {
  std::vector<Tri> nb(mesh.triangles.size(), Tri{kNoIndex, kNoIndex, kNoIndex});
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[t][(i + 1) % 3], b = mesh.triangles[t][(i + 2) % 3];
      for (std::size_t u = 0; u < mesh.triangles.size(); ++u)
        for (int j = 0; j < 3; ++j)
          if (mesh.triangles[u][(j + 1) % 3] == b && mesh.triangles[u][(j + 2) % 3] == a)
            nb[t][i] = static_cast<std::uint32_t>(u);
    }
  return nb;
}

std::string all_problems(const CheckReport& r) {
  std::string text;
  for (const auto& p : r.problems) text += p + "\n";
  return text;
}

// True when some reported problem contains every one of the given fragments.
bool reports(const CheckReport& r, std::initializer_list<std::string> fragments) {
  for (const auto& p : r.problems) {
    bool all = true;
    for (const auto& f : fragments) all = all && p.find(f) != std::string::npos;
    if (all) return true;
  }
  return false;
}

testing::AssertionResult is_valid(const CheckReport& r) {
  if (r.ok && r.problem_count == 0 && r.problems.empty()) return testing::AssertionSuccess();
  return testing::AssertionFailure() << r.problem_count << " problems:\n" << all_problems(r);
}

// Not ok, consistently counted, and one problem names all the fragments.
testing::AssertionResult has_problem(const CheckReport& r,
                                     std::initializer_list<std::string> fragments) {
  if (!r.ok && r.problem_count >= r.problems.size() && reports(r, fragments))
    return testing::AssertionSuccess();
  return testing::AssertionFailure() << "no problem names all of the fragments; got "
                                     << r.problem_count << ":\n" << all_problems(r);
}

#define EXPECT_VALID(report) EXPECT_TRUE(is_valid(report))
#define EXPECT_REPORTS(report, ...) EXPECT_TRUE(has_problem((report), {__VA_ARGS__}))

TriMesh unit_square(Tri first, Tri second) {
  return make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {first, second});
}

// Center 0 and six vertices around it: the center is interior, winding once.
TriMesh hexagon_fan() {
  std::vector<Point> points{{0, 0}};
  for (int k = 0; k < 6; ++k) {
    const double angle = k * std::acos(-1.0) / 3.0;
    points.push_back({std::cos(angle), std::sin(angle)});
  }
  std::vector<Tri> tris;
  for (std::uint32_t k = 0; k < 6; ++k) tris.push_back({0, 1 + k, 1 + (k + 1) % 6});
  return make_mesh(points, tris);
}

// Outer square 0-3 (side 3), inner square 4-7 (the hole), a point 8 in the hole and a
// duplicate 9 of vertex 0; neither of the last two is used by a triangle.
Pslg square_with_hole_input() {
  Pslg in;
  in.points = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1.5, 1.5}, {0, 0}};
  in.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1},
                 {4, 5, 2}, {5, 6, 2}, {6, 7, 2}, {7, 4, 2}};
  in.holes = {{1.5, 1.5}};
  return in;
}

TriMesh square_with_hole() {
  const Pslg in = square_with_hole_input();
  return make_mesh(in.points,
                   {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                    {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}},
                   in.segments);
}

// ---------------------------------------------------------------- valid meshes

TEST(MeshCheck, SquareSplitEitherWayIsValid) {
  // All four corners are cocircular: both diagonals are Delaunay (incircle == 0).
  EXPECT_VALID(check_mesh(unit_square({0, 1, 2}, {0, 2, 3})));
  EXPECT_VALID(check_mesh(unit_square({0, 1, 3}, {1, 2, 3})));
}

TEST(MeshCheck, HexagonFanWithNeighborsIsValid) {
  TriMesh mesh = hexagon_fan();
  mesh.neighbors = brute_force_neighbors(mesh);
  EXPECT_VALID(check_mesh(mesh));
}

TEST(MeshCheck, SquareWithHoleMatchesItsInput) {
  const Pslg in = square_with_hole_input();
  TriMesh mesh = square_with_hole();
  mesh.neighbors = brute_force_neighbors(mesh);
  EXPECT_VALID(check_mesh(mesh, &in));
}

TEST(MeshCheck, EmptyMeshIsValid) {
  EXPECT_VALID(check_mesh(TriMesh{}));
  EXPECT_VALID(check_mesh(make_mesh({{0, 0}, {1, 1}}, {})));
}

TEST(MeshCheck, SegmentSplitBySteinerVertexIsCovered) {
  // Input segment 0-1 along y = 0 is split at the Steiner vertex 3.
  Pslg in;
  in.points = {{0, 0}, {2, 0}, {1, 2}};
  in.segments = {{0, 1, 0}};
  TriMesh mesh = make_mesh({{0, 0}, {2, 0}, {1, 2}, {1, 0}}, {{0, 3, 2}, {3, 1, 2}},
                           {{0, 3, 0}, {3, 1, 0}});
  EXPECT_VALID(check_mesh(mesh, &in));

  // Without segments listed the cover is still there; listing only one piece is wrong.
  mesh.segments.clear();
  EXPECT_VALID(check_mesh(mesh, &in));
  mesh.segments = {{0, 3, 0}};
  EXPECT_REPORTS(check_mesh(mesh, &in), "input segment 0", "piece (1 3)", "not listed");
}

TEST(MeshCheck, SegmentThroughRoundedCrossingPointIsCovered) {
  // Vertex 3 is a crossing point rounded off the segment by 1e-12 (|ab| = 2): accepted.
  Pslg in;
  in.points = {{0, 0}, {2, 0}, {1, 2}};
  in.segments = {{0, 1, 0}};
  TriMesh mesh = make_mesh({{0, 0}, {2, 0}, {1, 2}, {1, 1e-12}}, {{0, 3, 2}, {3, 1, 2}});
  EXPECT_VALID(check_mesh(mesh, &in));

  // 1e-6 off is no rounding error: the chain 0-3-1 bends away from the segment, and there
  // is no direct edge 0-1, so the segment cuts through the triangles below the bend.
  mesh.points[3].y = 1e-6;
  mesh.points.push_back({1, -2});
  mesh.triangles.insert(mesh.triangles.end(), {{0, 4, 3}, {3, 4, 1}});
  EXPECT_REPORTS(check_mesh(mesh, &in), "input segment 0", "not covered", "passes through");
}

TEST(MeshCheck, VertexNearASegmentDoesNotDivertItsChain) {
  // Vertex 4 sits 1e-10 above segment 0-1 (within the 1e-9 |ab| tolerance) and is joined
  // to 0 and 3, but the segment is the listed chain 0-3-1 below it. Taking the nearest
  // step blindly would walk 0-4-3 and complain that 0-4 is not listed.
  Pslg in;
  in.points = {{0, 0}, {4, 0}, {2, 2}};
  in.segments = {{0, 1, 0}};
  TriMesh mesh = make_mesh({{0, 0}, {4, 0}, {2, 2}, {2, 0}, {1, 1e-10}, {2, -2}},
                           {{0, 3, 4}, {0, 4, 2}, {4, 3, 2}, {3, 1, 2}, {0, 5, 3}, {3, 5, 1}},
                           {{0, 3, 0}, {3, 1, 0}});
  EXPECT_VALID(check_mesh(mesh, &in, {.delaunay = false}));

  // A dead end: now 4 hangs off 0 in a stray (overlapping) triangle and leads nowhere;
  // with no segments listed, the nearest-step walk enters 4 and must back out to 0-3-1.
  mesh.points.push_back({1, -1});
  mesh.triangles = {{0, 3, 2}, {3, 1, 2}, {0, 5, 3}, {3, 5, 1}, {0, 6, 4}};
  mesh.segments.clear();
  const auto r = check_mesh(mesh, &in, {.delaunay = false});
  EXPECT_FALSE(r.ok);  // the stray triangle overlaps others...
  EXPECT_FALSE(reports(r, {"input segment"})) << all_problems(r);  // ...but 0-1 is covered
}

TEST(MeshCheck, SegmentEndpointDuplicateIsRepresentedByItsTwin) {
  // Input segment 9-1 uses the unused duplicate 9 of vertex 0: the edge 0-1 covers it.
  Pslg in = square_with_hole_input();
  in.segments.push_back({9, 1, 0});
  EXPECT_VALID(check_mesh(square_with_hole(), &in));
}

// ---------------------------------------------------------------- defects

TEST(MeshCheck, DetectsClockwiseTriangle) {
  const auto r = check_mesh(unit_square({0, 2, 1}, {0, 2, 3}));
  EXPECT_REPORTS(r, "triangle 0 (vertices 0 2 1)", "clockwise");
}

TEST(MeshCheck, DetectsDegenerateTriangle) {
  const auto r = check_mesh(make_mesh({{0, 0}, {1, 1}, {3, 3}}, {{0, 1, 2}}));
  EXPECT_REPORTS(r, "triangle 0", "degenerate");
  EXPECT_EQ(r.problem_count, 1u) << all_problems(r);
}

TEST(MeshCheck, DetectsIndexOutOfRange) {
  const auto r = check_mesh(unit_square({0, 1, 2}, {0, 2, 7}));
  EXPECT_REPORTS(r, "triangle 1", "vertex 7", "4 vertices");
}

TEST(MeshCheck, DetectsRepeatedVertexAndRepeatedTriangle) {
  EXPECT_REPORTS(check_mesh(unit_square({0, 1, 2}, {0, 2, 2})), "triangle 1", "same vertex twice");
  // Listed twice with opposite orientation: every edge then looks shared by two triangles.
  EXPECT_REPORTS(check_mesh(unit_square({0, 1, 2}, {2, 1, 0})), "triangle 0", "triangle 1",
                 "same three vertices");
}

TEST(MeshCheck, DetectsEdgeUsedThreeTimes) {
  // Edge 0-1 borders triangles above (2 and 4) and one below (3).
  const auto mesh = make_mesh({{0, 0}, {1, 0}, {0.5, 1}, {0.5, -1}, {0.5, 2}},
                              {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  EXPECT_REPORTS(check_mesh(mesh), "edge (0 1)", "used by 3 triangles", "0, 2, 1");
}

TEST(MeshCheck, DetectsTwoTrianglesOnTheSameSideOfAnEdge) {
  const auto mesh = make_mesh({{0, 0}, {1, 0}, {0.5, 1}, {0.5, 2}}, {{0, 1, 2}, {0, 1, 3}});
  const auto r = check_mesh(mesh);
  EXPECT_REPORTS(r, "edge (0 1)", "same direction", "same side");
  // The overlap also puts vertex 2 inside triangle 1.
  EXPECT_REPORTS(r, "vertex 2", "inside triangle 1");
}

TEST(MeshCheck, DetectsFoldWindingTwiceAroundAVertex) {
  // Twelve spokes at 60 degree steps, going round twice (radius 1, then radius 2): every
  // spoke is shared by two triangles in opposite directions, yet the fan covers twice.
  std::vector<Point> points{{0, 0}};
  for (int k = 0; k < 12; ++k) {
    const double angle = k * std::acos(-1.0) / 3.0, radius = k < 6 ? 1.0 : 2.0;
    points.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  std::vector<Tri> tris;
  for (std::uint32_t k = 0; k < 12; ++k) tris.push_back({0, 1 + k, 1 + (k + 1) % 12});
  const auto r = check_mesh(make_mesh(points, tris), nullptr, {.delaunay = false});
  EXPECT_REPORTS(r, "vertex 0", "wind 2 times");
}

// A sliver whose corner at vertex 4 is nearly pi: (0.15, 0.75) lies a hair above the line
// from (0, 0) to (0.5, 2.5) (0.15 is not a double), so the triangle is counterclockwise,
// exactly. The rounded cross product at that corner came out negative, the angle -pi, and
// the fan round vertex 4 summed to 0: a valid mesh reported as overlapping (fuzzing).
TEST(MeshCheck, ASliverWithACornerOfNearlyPiClosesItsFan) {
  const std::vector<Point> points{{0, 5}, {1, 5}, {0, 0}, {0, 1}, {0.15, 0.75}, {1, 0}, {0.5, 2.5}};
  ASSERT_GT(orient2d(points[2], points[6], points[4]), 0.0);
  const std::vector<Tri> tris{{2, 4, 3}, {2, 6, 4}, {1, 6, 5}, {0, 3, 6}, {3, 4, 6}, {6, 1, 0}, {6, 2, 5}};
  const auto r = check_mesh(make_mesh(points, tris), nullptr, {.delaunay = false});
  EXPECT_TRUE(r.ok) << (r.problems.empty() ? "" : r.problems.front());
}

TEST(MeshCheck, DetectsStrayVertexInsideTriangleOrOnEdge) {
  // Vertex 3 is used by no triangle, which is allowed, but it lies inside triangle 0.
  auto r = check_mesh(make_mesh({{0, 0}, {4, 0}, {0, 4}, {1, 1}}, {{0, 1, 2}}));
  EXPECT_REPORTS(r, "vertex 3", "inside triangle 0 (vertices 0 1 2)");
  EXPECT_EQ(r.problem_count, 1u) << all_problems(r);

  r = check_mesh(make_mesh({{0, 0}, {4, 0}, {0, 4}, {2, 2}}, {{0, 1, 2}}));
  EXPECT_REPORTS(r, "vertex 3", "on the edge (1 2)");

  // On an interior edge: one report, not one per adjacent triangle.
  TriMesh square = unit_square({0, 1, 2}, {0, 2, 3});
  square.points.push_back({0.5, 0.5});
  r = check_mesh(square);
  EXPECT_REPORTS(r, "vertex 4", "on the edge (0 2)");
  EXPECT_EQ(r.problem_count, 1u) << all_problems(r);

  // Unused vertices outside, or duplicating a corner, are fine.
  EXPECT_VALID(check_mesh(make_mesh({{0, 0}, {4, 0}, {0, 4}, {4, 4}, {4, 0}}, {{0, 1, 2}})));
}

TEST(MeshCheck, DetectsNonDelaunayEdgeUnlessItIsASegment) {
  // Long diagonal 0-2 of a flat rhombus: vertex 3 is inside the circumcircle of (0 1 2).
  const std::vector<Point> rhombus{{-2, 0}, {0, -1}, {2, 0}, {0, 1}};
  TriMesh mesh = make_mesh(rhombus, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_REPORTS(check_mesh(mesh), "edge (0 2)", "not Delaunay");
  EXPECT_VALID(check_mesh(mesh, nullptr, {.delaunay = false}));

  mesh.segments = {{2, 0, 0}};  // either direction names the edge
  EXPECT_VALID(check_mesh(mesh));

  EXPECT_VALID(check_mesh(make_mesh(rhombus, {{0, 1, 3}, {1, 2, 3}})));
}

TEST(MeshCheck, DetectsWrongNeighbors) {
  TriMesh mesh = hexagon_fan();
  mesh.neighbors = brute_force_neighbors(mesh);
  // Triangle 0 = (0 1 2): neighbor 0 is across the boundary edge 1-2.
  ASSERT_EQ(mesh.neighbors[0][0], kNoIndex);
  ASSERT_EQ(mesh.neighbors[0][1], 1u);

  TriMesh wrong = mesh;
  wrong.neighbors[0][1] = 3;
  EXPECT_REPORTS(check_mesh(wrong), "triangle 0", "neighbor 1", "is triangle 3",
                 "expected triangle 1");

  wrong = mesh;
  wrong.neighbors[0][0] = 4;  // a boundary edge must say kNoIndex
  EXPECT_REPORTS(check_mesh(wrong), "neighbor 0", "expected none");

  wrong = mesh;
  wrong.neighbors[0][2] = kNoIndex;  // and an interior edge must not
  EXPECT_REPORTS(check_mesh(wrong), "neighbor 2", "is none");

  wrong = mesh;
  wrong.neighbors.pop_back();
  EXPECT_REPORTS(check_mesh(wrong), "neighbors for 5 triangles");
}

TEST(MeshCheck, DetectsMovedInputVertex) {
  const Pslg in = square_with_hole_input();
  TriMesh mesh = square_with_hole();
  mesh.points[5].x = std::nextafter(mesh.points[5].x, 3.0);  // one ulp
  EXPECT_REPORTS(check_mesh(mesh, &in), "vertex 5", "input vertex 5");

  // Bit for bit: -0.0 is not the input's 0.0 even though they compare equal.
  mesh = square_with_hole();
  mesh.points[0].y = -0.0;
  EXPECT_REPORTS(check_mesh(mesh, &in), "vertex 0", "input vertex 0");

  mesh = square_with_hole();
  mesh.points.resize(5);
  mesh.triangles.clear();
  EXPECT_REPORTS(check_mesh(mesh, &in), "5 vertices", "10 input vertices");
}

TEST(MeshCheck, DetectsUncoveredInputSegment) {
  // The square split along 0-2 cannot cover input segment 1-3.
  Pslg in;
  in.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  in.segments = {{0, 1, 0}, {1, 3, 0}};
  in.first_index = 1;
  const TriMesh mesh = unit_square({0, 1, 2}, {0, 2, 3});
  const auto r = check_mesh(mesh, &in);
  EXPECT_REPORTS(r, "input segment 2 (vertices 2 4)", "not covered", "passes through triangle");
  EXPECT_EQ(r.problem_count, 1u) << all_problems(r);
}

TEST(MeshCheck, SegmentsOutsideTheDomainNeedNoEdges) {
  // Triangle-style triangulators remove the triangles in holes and outside the outer
  // boundary, and with them the edges of segments there. Vertex 10 is added in the hole.
  Pslg in = square_with_hole_input();
  in.points.push_back({1.2, 1.5});
  TriMesh mesh = square_with_hole();
  mesh.points = in.points;

  // Wholly inside the hole (both ends unused): nothing to cover.
  in.segments.push_back({8, 10, 0});
  EXPECT_VALID(check_mesh(mesh, &in));

  // From corner 0 into the hole: along the mesh edge 0-4, then through the hole. The part
  // inside the domain is covered, but must be listed like every other segment piece.
  in.segments.push_back({0, 8, 0});
  EXPECT_REPORTS(check_mesh(mesh, &in), "input segment 9", "piece (0 4)", "not listed");
  mesh.segments.push_back({0, 4, 0});
  EXPECT_VALID(check_mesh(mesh, &in));

  // A lone segment encloses nothing, so nothing is left of its triangulation.
  Pslg lone;
  lone.points = {{0, 0}, {1, 0}, {0, 1}};
  lone.segments = {{0, 1, 0}};
  EXPECT_VALID(check_mesh(make_mesh(lone.points, {}), &lone));
}

TEST(MeshCheck, DetectsHoleThatWasNotRemoved) {
  // Without the unused vertices 8 and 9: 8 would lie on the diagonals of the filled hole.
  Pslg in = square_with_hole_input();
  in.points.resize(8);
  in.holes = {{1.7, 1.2}, {1.5, 1.0}};  // the second on the hole's boundary edge 4-5
  TriMesh ring = square_with_hole();
  ring.points.resize(8);
  EXPECT_VALID(check_mesh(ring, &in));

  TriMesh filled = ring;
  filled.triangles.insert(filled.triangles.end(), {{4, 5, 6}, {4, 6, 7}});
  const auto r = check_mesh(filled, &in, {.delaunay = false, .max_problems = 50});
  EXPECT_REPORTS(r, "hole 0", "inside triangle 8 (vertices 4 5 6)", "not removed");
  EXPECT_FALSE(reports(r, {"hole 1"})) << all_problems(r);  // on a segment: fine

  // Half a hole: the point sits on the unconstrained diagonal 4-6 of the filled hole, and
  // the triangle on the other side was removed but this one was not.
  in.holes = {{1.7, 1.7}};
  filled.triangles.pop_back();
  EXPECT_REPORTS(check_mesh(filled, &in, {.delaunay = false}), "hole 0",
                 "on the edge (4 6), not a segment, of triangle 8", "not removed");
  filled.segments.push_back({4, 6, 0});  // as a segment, the diagonal stops the hole
  EXPECT_VALID(check_mesh(filled, &in, {.delaunay = false}));
}

TEST(MeshCheck, NamesThingsWithTheFilesFirstIndex) {
  TriMesh mesh = unit_square({0, 1, 2}, {0, 3, 2});
  mesh.first_index = 1;
  EXPECT_REPORTS(check_mesh(mesh), "triangle 2 (vertices 1 4 3)", "clockwise");
}

TEST(MeshCheck, KeepsOnlyMaxProblemsButCountsAll) {
  // 30 clockwise triangles far apart: 30 problems and nothing else.
  TriMesh mesh;
  for (std::uint32_t k = 0; k < 30; ++k) {
    const double x = 10.0 * k;
    mesh.points.insert(mesh.points.end(), {{x, 0}, {x + 1, 0}, {x, 1}});
    mesh.triangles.push_back({3 * k, 3 * k + 2, 3 * k + 1});
  }
  const auto r = check_mesh(mesh, nullptr, {.delaunay = true, .max_problems = 5});
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.problems.size(), 5u);
  EXPECT_EQ(r.problem_count, 30u);
}

// An n x n grid of slightly perturbed cells, each split along its Delaunay diagonal.
TriMesh perturbed_grid(std::uint32_t n) {
  TriMesh mesh;
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) {
      const double jitter = ((i * 7919u + j * 104729u) % 1000) * 1e-5;  // < 0.01
      mesh.points.push_back({i + jitter, j - jitter});
    }
  auto at = [&](std::uint32_t i, std::uint32_t j) { return j * (n + 1) + i; };
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      // Keep the diagonal a-c unless d is strictly inside the circle (a b c).
      const auto& p = mesh.points;
      if (incircle(p[a], p[b], p[c], p[d]) <= 0) {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      } else {
        mesh.triangles.push_back({a, b, d});
        mesh.triangles.push_back({b, c, d});
      }
    }
  mesh.input_vertex_count = mesh.points.size();
  return mesh;
}

TEST(MeshCheck, LargePerturbedGridIsValid) {
  // 80000 triangles: enough that a quadratic mistake would make this test crawl.
  EXPECT_VALID(check_mesh(perturbed_grid(200)));
}

TEST(MeshCheck, LongThinFanIsValid) {
  // A circle and its center: every triangle spans the whole radius, the case that makes
  // bucket grids quadratic. (Rounded circle points are not exactly cocircular, so the
  // Delaunay test is off.)
  const std::uint32_t n = 20000;
  std::vector<Point> points{{0, 0}};
  for (std::uint32_t k = 0; k < n; ++k) {
    const double angle = 2.0 * std::acos(-1.0) * k / n;
    points.push_back({std::cos(angle), std::sin(angle)});
  }
  std::vector<Tri> tris;
  for (std::uint32_t k = 0; k < n; ++k) tris.push_back({0, 1 + k, 1 + (k + 1) % n});
  EXPECT_VALID(check_mesh(make_mesh(points, tris), nullptr, {.delaunay = false}));
}

TEST(MeshCheck, FindsEveryStrayVertexThatBruteForceFinds) {
  // Unused vertices scattered over a grid mesh, some duplicating its vertices and some at
  // midpoints of its edges (exactly on the edge whenever the midpoint rounds onto it): the
  // tree-pruned search must report exactly the (vertex, triangle) pairs that a brute-force
  // scan with the same exact predicate finds.
  TriMesh mesh = perturbed_grid(12);
  const std::size_t used = mesh.points.size();
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> coord(-1.0, 13.0);
  std::uniform_int_distribution<std::size_t> pick_vertex(0, used - 1);
  std::uniform_int_distribution<std::size_t> pick_triangle(0, mesh.triangles.size() - 1);
  for (int k = 0; k < 300; ++k) {
    const auto& tri = mesh.triangles[pick_triangle(rng)];
    const Point p = mesh.points[tri[k % 3]], q = mesh.points[tri[(k + 1) % 3]];
    switch (k % 3) {
      case 0: mesh.points.push_back({coord(rng), coord(rng)}); break;
      case 1: mesh.points.push_back(mesh.points[pick_vertex(rng)]); break;  // allowed
      default: mesh.points.push_back({0.5 * (p.x + q.x), 0.5 * (p.y + q.y)}); break;
    }
  }
  // Expected: one report per (vertex, triangle) strictly inside, and one per (vertex,
  // undirected edge) for a vertex in the relative interior of an edge.
  std::size_t inside = 0;
  std::set<std::array<std::uint32_t, 3>> on_edges;
  for (std::uint32_t v = used; v < mesh.points.size(); ++v)
    for (const auto& tri : mesh.triangles) {
      const Point &a = mesh.points[tri[0]], &b = mesh.points[tri[1]], &c = mesh.points[tri[2]];
      const Point& q = mesh.points[v];
      const double o[3] = {orient2d(b, c, q), orient2d(c, a, q), orient2d(a, b, q)};
      if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
      const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
      if (zeros == 0) ++inside;
      if (zeros != 1) continue;
      const int i = o[0] == 0 ? 0 : (o[1] == 0 ? 1 : 2);
      const std::uint32_t e0 = tri[(i + 1) % 3], e1 = tri[(i + 2) % 3];
      on_edges.insert({v, std::min(e0, e1), std::max(e0, e1)});
    }
  const std::size_t expected = inside + on_edges.size();
  // The scenario must exercise both kinds of report.
  ASSERT_GT(on_edges.size(), 10u);
  ASSERT_GT(expected, 50u);  // the scenario must actually exercise the search
  const auto r = check_mesh(mesh, nullptr, {.delaunay = true, .max_problems = 0});
  EXPECT_EQ(r.problem_count, expected);
  EXPECT_TRUE(r.problems.empty());
}

// ---------------------------------------------------------------- quality

TEST(Quality, RightIsoscelesTriangleAngles) {
  const Point a{0, 0}, b{1, 0}, c{0, 1};
  EXPECT_NEAR(triangle_min_angle_deg(a, b, c), 45.0, 1e-12);
  EXPECT_NEAR(triangle_max_angle_deg(a, b, c), 90.0, 1e-12);
  // Orientation does not matter.
  EXPECT_NEAR(triangle_min_angle_deg(a, c, b), 45.0, 1e-12);

  const auto stats = angle_stats(make_mesh({a, b, c}, {{0, 1, 2}}));
  EXPECT_NEAR(stats.min_angle_deg, 45.0, 1e-12);
  EXPECT_NEAR(stats.max_angle_deg, 90.0, 1e-12);
}

TEST(Quality, AngleStatsOverSeveralTriangles) {
  // Equilateral (60/60/60) next to a right isosceles triangle: 45 and 90 overall.
  const double h = std::sqrt(3.0) / 2.0;
  const auto stats = angle_stats(make_mesh({{0, 0}, {1, 0}, {0.5, h}, {10, 0}, {11, 0}, {10, 1}},
                                           {{0, 1, 2}, {3, 4, 5}}));
  EXPECT_NEAR(stats.min_angle_deg, 45.0, 1e-12);
  EXPECT_NEAR(stats.max_angle_deg, 90.0, 1e-12);

  const auto equilateral = angle_stats(make_mesh({{0, 0}, {1, 0}, {0.5, h}}, {{0, 1, 2}}));
  EXPECT_NEAR(equilateral.min_angle_deg, 60.0, 1e-9);
  EXPECT_NEAR(equilateral.max_angle_deg, 60.0, 1e-9);

  const auto none = angle_stats(TriMesh{});
  EXPECT_EQ(none.min_angle_deg, 0.0);
  EXPECT_EQ(none.max_angle_deg, 0.0);
}

TEST(Quality, CanonicalTrianglesCompareTriangleSets) {
  TriMesh a = hexagon_fan();
  TriMesh b = a;
  std::reverse(b.triangles.begin(), b.triangles.end());
  for (auto& t : b.triangles) std::rotate(t.begin(), t.begin() + 1, t.end());
  ASSERT_NE(a.triangles, b.triangles);
  EXPECT_EQ(canonical_triangles(a), canonical_triangles(b));
  EXPECT_EQ(canonical_triangles(a).front(), (Tri{0, 1, 2}));

  TriMesh c = a;  // a different triangle
  c.triangles[0] = {0, 1, 3};
  EXPECT_NE(canonical_triangles(a), canonical_triangles(c));
  TriMesh d = a;  // the same vertices, opposite orientation
  d.triangles[0] = {0, 2, 1};
  EXPECT_NE(canonical_triangles(a), canonical_triangles(d));
}

}  // namespace
}  // namespace meshstep
