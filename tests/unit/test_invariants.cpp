// The cheap checks before a mesh is written (delaunay/invariants.hpp): quiet on every good
// triangulation, on both data structures, and each one speaks when its invariant is broken
// by hand: a folded face, a vertex in no face, a hull turned inside out.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshstep/delaunay/invariants.hpp"
#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"

namespace meshstep {
namespace {

std::vector<Point> random_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> p(n);
  for (Point& q : p) q = {u(rng), u(rng)};
  return p;
}

// A square grid: many collinear points on the hull, cocircular ones inside.
std::vector<Point> grid(int n) {
  std::vector<Point> p;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) p.push_back({double(i), double(j)});
  return p;
}

std::string failure(auto&& f) {
  try {
    f();
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

template <class Mesh>
class Invariants : public ::testing::Test {};
using Structures = ::testing::Types<Tds, Dcel>;
TYPED_TEST_SUITE(Invariants, Structures);

TYPED_TEST(Invariants, HoldOnGoodTriangulations) {
  for (const auto& points : {random_points(2000, 1), grid(12), std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}}) {
    Triangulation<TypeParam> tri(points, Insertion::flip);
    tri.insert_all();
    EXPECT_NO_THROW(check_whole_triangulation(tri));
  }
  std::vector<Point> twice = grid(5);
  const std::vector<Point> again = grid(5);
  twice.insert(twice.end(), again.begin(), again.end());  // duplicates are merged, not lost
  Triangulation<TypeParam> tri(twice, Insertion::cavity);
  tri.insert_all();
  EXPECT_NO_THROW(check_whole_triangulation(tri));
}

// A vertex that is in the points but in no face: what the wrong mesh of issue 16 had.
TYPED_TEST(Invariants, NameAVertexInNoFace) {
  Triangulation<TypeParam> tri(random_points(50, 2), Insertion::flip);
  tri.insert_all();
  tri.add_point({0.5, 0.5});
  EXPECT_NE(failure([&] { check_whole_triangulation(tri); }).find("1 of its 51 vertices are the corner of no face"),
            std::string::npos);
}

// Flipping an edge whose quadrilateral is not convex folds a face over its neighbour.
TYPED_TEST(Invariants, NameAFoldedFace) {
  Triangulation<TypeParam> tri({{0, 0}, {4, 0}, {1.5, 1}, {2, 3}, {2, -3}}, Insertion::flip);
  tri.insert_all();
  ASSERT_NO_THROW(check_whole_triangulation(tri));
  // The quadrilateral round edge (0,0)-(1.5,1) is (0,0), (2,-3), (1.5,1), (2,3), not convex
  // at (1.5,1): the flip to (2,-3)-(2,3) makes a face that is clockwise.
  const HalfEdge h = tri.find_edge(0, 2);
  ASSERT_NE(h, kNone);
  tri.mesh().flip(h);
  EXPECT_NE(failure([&] { check_whole_triangulation(tri); }).find("is not counterclockwise"), std::string::npos);
}

// Flipping a hull edge with its ghost face turns the hull the wrong way at a vertex.
TYPED_TEST(Invariants, NameAHullThatTurnsTheWrongWay) {
  Triangulation<TypeParam> tri({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}}, Insertion::flip);
  tri.insert_all();
  ASSERT_NO_THROW(check_whole_triangulation(tri));
  // The hull edge (0,0)-(4,0) with the ghost face beyond it: after the flip, the infinite
  // vertex is joined to (2,1), which becomes a hull vertex where the hull turns back.
  const HalfEdge h = tri.find_edge(0, 1);
  ASSERT_NE(h, kNone);
  tri.mesh().flip(h);
  EXPECT_NE(failure([&] { check_whole_triangulation(tri); }).find("hull turns the wrong way"), std::string::npos);
}

}  // namespace
}  // namespace meshstep
