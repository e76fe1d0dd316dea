// smallest_input_angle: where two segments meet at a vertex, the smallest angle between
// them, naming the vertex and both segments; segments listed twice, overlapping ones,
// zero-length ones and straight corners make no angle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "meshstep/pslg/input_angles.hpp"

namespace meshstep {
namespace {

Pslg with(std::vector<Point> points, std::vector<Segment> segments) {
  Pslg in;
  in.points = std::move(points);
  in.segments = std::move(segments);
  return in;
}

TEST(InputAngles, TheSmallestCornerOfAPolygonAndWhereItIs) {
  const double t = std::tan(10.0 * std::numbers::pi / 180.0);
  const auto a = smallest_input_angle(with({{0, 0}, {10, 0}, {10, 10 * t}}, {{0, 1}, {1, 2}, {2, 0}}));
  ASSERT_TRUE(a);
  EXPECT_NEAR(a->degrees, 10.0, 1e-9);
  EXPECT_EQ(a->vertex, 0u);
  EXPECT_EQ(a->first, 0u);
  EXPECT_EQ(a->second, 2u);
  // A square: 90 at every corner, the first vertex named.
  const auto square = smallest_input_angle(with({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}));
  ASSERT_TRUE(square);
  EXPECT_NEAR(square->degrees, 90.0, 1e-9);
}

// Round the back of the directions (through +-180 degrees), and more than two segments.
TEST(InputAngles, FindsTheGapAcrossTheBackAndAmongManySegments) {
  // Directions 170 and -175 degrees from the origin: 15 degrees apart across the back.
  const double r = std::numbers::pi / 180.0;
  const auto a = smallest_input_angle(with({{0, 0}, {std::cos(170 * r), std::sin(170 * r)},
                                           {std::cos(-175 * r), std::sin(-175 * r)}, {1, 0}},
                                          {{0, 1}, {0, 2}, {0, 3}}));
  ASSERT_TRUE(a);
  EXPECT_NEAR(a->degrees, 15.0, 1e-9);
}

TEST(InputAngles, DuplicatesOverlapsAndPointsMakeNoAngle) {
  EXPECT_FALSE(smallest_input_angle(with({{0, 0}, {1, 0}, {2, 0}}, {})));
  EXPECT_FALSE(smallest_input_angle(with({{0, 0}, {1, 0}}, {{0, 1}, {1, 0}})));         // listed twice
  EXPECT_FALSE(smallest_input_angle(with({{0, 0}, {1, 0}, {2, 0}}, {{0, 1}, {0, 2}})));  // overlapping
  EXPECT_FALSE(smallest_input_angle(with({{0, 0}, {0, 0}, {1, 0}}, {{0, 1}, {0, 2}})));  // zero length
  EXPECT_FALSE(smallest_input_angle(with({{0, 0}, {1, 0}, {2, 0}}, {{0, 1}, {1, 2}})));  // straight on
}

}  // namespace
}  // namespace meshstep
