// TriangleField: the value of the triangle holding a point, on meshes of a few to thousands
// of triangles, with points on edges, at vertices and outside.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/geometry/triangle_field.hpp"

namespace meshstep {
namespace {

TriangleField field_of(const TriMesh& m) {
  TriangleField field;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& v = m.triangles[t];
    field.add(m.points[v[0]], m.points[v[1]], m.points[v[2]], static_cast<double>(t));
  }
  field.build();
  return field;
}

TEST(TriangleField, EveryCentroidFindsItsTriangle) {
  for (const std::size_t n : {3u, 5u, 12u, 100u, 5000u}) {
    SCOPED_TRACE(std::to_string(n) + " points");
    std::mt19937_64 rng(n);
    std::uniform_real_distribution<double> u(-3.0, 7.0);
    Pslg in;
    for (std::size_t i = 0; i < n; ++i) in.points.push_back({u(rng), u(rng)});
    const TriMesh m = triangulate(in);
    const TriangleField field = field_of(m);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const auto& v = m.triangles[t];
      const Point c{(m.points[v[0]].x + m.points[v[1]].x + m.points[v[2]].x) / 3.0,
                    (m.points[v[0]].y + m.points[v[1]].y + m.points[v[2]].y) / 3.0};
      ASSERT_EQ(field.at(c, -1.0), static_cast<double>(t)) << "triangle " << t;
      // A vertex belongs to some triangle around it.
      ASSERT_GE(field.at(m.points[v[0]], -1.0), 0.0);
    }
    EXPECT_EQ(field.at({100.0, 100.0}, -1.0), -1.0);
  }
}

TEST(TriangleField, EmptyAndDegenerateExtents) {
  TriangleField empty;
  empty.build();
  EXPECT_EQ(empty.at({0, 0}, 7.0), 7.0);
  // One triangle: a single cell.
  TriangleField one;
  one.add({0, 0}, {1, 0}, {0, 1}, 3.0);
  one.build();
  EXPECT_EQ(one.at({0.25, 0.25}, -1.0), 3.0);
  EXPECT_EQ(one.at({0.5, 0.5}, -1.0), 3.0);  // on the hypotenuse: closed
  EXPECT_EQ(one.at({0.75, 0.75}, -1.0), -1.0);
}

// Over a triangle: the smallest positive value of the triangles it overlaps, touching not
// counting, and no positive value at all giving `none`.
TEST(TriangleField, SmallestPositiveValueOverATriangle) {
  TriangleField f;
  f.add({0, 0}, {1, 0}, {0, 1}, 0.5);   // lower left
  f.add({1, 0}, {1, 1}, {0, 1}, 0.25);  // upper right of the unit square
  f.add({2, 0}, {3, 0}, {2, 1}, -1.0);  // no bound
  f.build();
  EXPECT_EQ(f.min_positive_over({0.1, 0.1}, {0.3, 0.1}, {0.1, 0.3}, -1.0), 0.5);         // inside one
  EXPECT_EQ(f.min_positive_over({0.2, 0.2}, {0.9, 0.6}, {0.3, 0.9}, -1.0), 0.25);        // across the diagonal
  EXPECT_EQ(f.min_positive_over({-1, -1}, {5, -1}, {-1, 5}, -1.0), 0.25);                // covering all
  EXPECT_EQ(f.min_positive_over({1, 0}, {2, 0}, {1, 1}, -1.0), -1.0);                    // touching only
  EXPECT_EQ(f.min_positive_over({2.1, 0.1}, {2.5, 0.1}, {2.1, 0.5}, -1.0), -1.0);        // no positive value
  EXPECT_EQ(f.min_positive_over({10, 10}, {11, 10}, {10, 11}, -1.0), -1.0);              // far away
}

}  // namespace
}  // namespace meshstep
