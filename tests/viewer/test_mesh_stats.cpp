// The statistics' scan of a mesh (mesh_stats.hpp) against the trigonometry it avoids: for
// random triangles and for triangles whose smallest angle sits exactly on a histogram bin's
// edge, the same bins, the same extreme angles, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "mesh_stats.hpp"
#include "meshstep/refine/quality.hpp"

namespace meshstep::viewer {
namespace {

// What measure() computed before it compared sin^2: asin and acos for every triangle.
Stats by_trigonometry(const scene::MeshLayer& mesh) {
  Stats s;
  s.min_angle = 180.0;
  for (const auto& t : mesh.triangles) {
    const auto q = quality::shape(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    const double smallest = q.min_angle_deg();
    s.min_angle = std::min(s.min_angle, smallest);
    s.max_angle = std::max(s.max_angle, q.max_angle_deg());
    s.histogram[static_cast<std::size_t>(std::clamp(smallest / 60.0 * 18.0, 0.0, 17.0))] += 1.0f;
  }
  s.triangles = mesh.triangles.size();
  return s;
}

void add_triangle(scene::MeshLayer& m, Point a, Point b, Point c) {
  const auto n = static_cast<std::uint32_t>(m.points.size());
  m.points.insert(m.points.end(), {a, b, c});
  m.triangles.push_back({n, n + 1, n + 2});
}

TEST(MeshStats, BinsAndExtremesAsTheTrigonometryGivesThem) {
  scene::MeshLayer m;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int i = 0; i < 20000; ++i)
    add_triangle(m, {coordinate(random), coordinate(random)}, {coordinate(random), coordinate(random)},
                 {coordinate(random), coordinate(random)});
  // Isosceles triangles whose apex, their smallest angle, is a bin's edge (k * 10/3
  // degrees), and a hair either side of it; an equilateral one; a degenerate one.
  for (int k = 1; k < 18; ++k)
    for (const double hair : {-1e-13, 0.0, 1e-13}) {
      const double apex = (k * 10.0 / 3.0) * std::numbers::pi / 180.0 + hair;
      add_triangle(m, {0, 0}, {std::cos(0.5 * apex), std::sin(0.5 * apex)}, {std::cos(0.5 * apex), -std::sin(0.5 * apex)});
    }
  add_triangle(m, {0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2.0});
  add_triangle(m, {0, 0}, {1, 0}, {2, 0});
  const Stats fast = measure(m, nullptr), slow = by_trigonometry(m);
  EXPECT_EQ(fast.histogram, slow.histogram);
  EXPECT_EQ(fast.min_angle, slow.min_angle);
  EXPECT_EQ(fast.max_angle, slow.max_angle);
  EXPECT_EQ(fast.triangles, m.triangles.size());
  EXPECT_EQ(fast.min_angle, 0.0);    // the degenerate triangle
  EXPECT_EQ(fast.max_angle, 180.0);  // and its straight angle
  // Every bin holds something, so a misplaced edge would show.
  for (const float count : fast.histogram) EXPECT_GT(count, 0.0f);
}

TEST(MeshStats, ExtremesOfWellShapedTriangles) {
  // No degenerate triangle: the extremes are those of the random ones, as computed one by one.
  scene::MeshLayer m;
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  for (int i = 0; i < 5000; ++i)
    add_triangle(m, {coordinate(random), coordinate(random)}, {coordinate(random) + 2.0, coordinate(random)},
                 {coordinate(random) + 1.0, coordinate(random) + 2.0});
  const Stats fast = measure(m, nullptr), slow = by_trigonometry(m);
  EXPECT_EQ(fast.histogram, slow.histogram);
  EXPECT_EQ(fast.min_angle, slow.min_angle);
  EXPECT_EQ(fast.max_angle, slow.max_angle);
  EXPECT_GT(fast.min_angle, 0.0);
  EXPECT_LT(fast.min_angle, 60.0);
  EXPECT_GT(fast.max_angle, 60.0);
  EXPECT_LT(fast.max_angle, 180.0);
}

TEST(MeshStats, AnEmptyMeshHasNoAngles) {
  const Stats s = measure(scene::MeshLayer{}, nullptr);
  EXPECT_EQ(s.triangles, 0u);
  EXPECT_EQ(s.min_angle, 0.0);
  EXPECT_EQ(s.max_angle, 0.0);
}

}  // namespace
}  // namespace meshstep::viewer
