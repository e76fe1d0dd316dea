// Inputs at the edges of the doubles: the reproducers of the hardening campaign (issue 16)
// as the cases they stand for, nearly collinear crossings whose rounded intersection lands
// off both segments, inputs scaled across the whole exponent range, and the rule that
// refuses coordinates too far apart in magnitude. Every mesh is checked by the full
// checker, on every data structure and insertion strategy.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "meshstep/error.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

using testing::triangulate_everywhere;

Pslg with_segments(std::vector<Point> points, std::vector<Segment> segments) {
  Pslg in;
  in.points = std::move(points);
  in.segments = std::move(segments);
  return in;
}

std::string refusal(const Pslg& in) {
  try {
    triangulate(in);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A segment that crosses a constrained one a hair from its own end vertex, which lies an
// ulp off that segment: the rounded crossing falls on the far side of the vertex, where
// splitting the constrained edge would fold a triangle over it. (Was: one triangle, with
// vertex 4 inside it, and exit 0.)
TEST(ExtremeInputs, CrossingRoundedNextToAVertexKeepsTheMeshValid) {
  const Pslg in = with_segments({{0, 0}, {1, 5}, {1, 0}, {0, 1}, {0.15, 0.75}, {1, 0}}, {{0, 1}, {2, 3}, {4, 5}});
  triangulate_everywhere(in, false);
  triangulate_everywhere(in, true);
}

// Coordinates 16 orders of magnitude apart, one segment sliding past a vertex along a
// nearly flat triangle. (Was: a segmentation fault in segment insertion.)
TEST(ExtremeInputs, SixteenOrdersOfMagnitudeApart) {
  const Pslg in = with_segments({{1.0, 0.0}, {0.0, 1.0}, {0.1, 0.7}, {0.0, 9233720368545808.0}, {2.0, 0.0}},
                                {{0, 1}, {3, 2}});
  triangulate_everywhere(in, false);
  triangulate_everywhere(in, true);
}

// Many segments through nearly one point, each end an ulp or so off the others' lines:
// crossings rounded next to vertices and to each other.
TEST(ExtremeInputs, PencilsOfNearlyConcurrentSegments) {
  std::mt19937_64 rng(5);
  for (int round = 0; round < 40; ++round) {
    Pslg in;
    const Point centre{0.3 + 0.01 * round, 0.7};
    for (int i = 0; i < 8; ++i) {
      const double angle = std::uniform_real_distribution<double>(0, M_PI)(rng);
      const double d = std::uniform_real_distribution<double>(0.1, 1.0)(rng);
      const double nudge = std::uniform_int_distribution<int>(-3, 3)(rng) * 0x1p-52;
      const Point a{centre.x + d * std::cos(angle), centre.y + d * std::sin(angle)};
      const Point b{centre.x - d * std::cos(angle) + nudge, centre.y - d * std::sin(angle)};
      const auto at = static_cast<std::uint32_t>(in.points.size());
      in.points.push_back(a);
      in.points.push_back(b);
      in.segments.push_back({at, at + 1, 1});
      if (i % 3 == 0) in.points.push_back({centre.x + nudge, centre.y - nudge});  // a vertex at the pencil's heart
    }
    SCOPED_TRACE("round " + std::to_string(round));
    triangulate_everywhere(in, round % 2 == 0);
  }
}

// The same input scaled by powers of two from 2^-900 to 2^900: exactly the same triangles
// (scaling is exact, and the predicates are exact in the whole window).
TEST(ExtremeInputs, ScalingByPowersOfTwoChangesNothing) {
  Pslg in = with_segments({{0, 0}, {3, 0}, {3, 2}, {0, 2}, {1, 1}, {2, 1}, {1.5, 1e-9}, {1.5, 1.9999999}},
                          {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {6, 7}});
  for (int i = 0; i < 30; ++i) in.points.push_back({0.1 * i, 1.0 + std::ldexp(1.0, -40 - i)});
  const TriMesh reference = triangulate(in);
  for (const int k : {-900, -600, -300, -100, 100, 300, 600, 900}) {
    Pslg scaled = in;
    for (Point& p : scaled.points) p = {std::ldexp(p.x, k), std::ldexp(p.y, k)};
    const TriMesh m = triangulate_everywhere(scaled);
    EXPECT_EQ(m.triangles, reference.triangles) << "scaled by 2^" << k;
    for (std::size_t v = 0; v < m.points.size(); ++v)
      EXPECT_EQ(m.points[v].x, std::ldexp(reference.points[v].x, k)) << "vertex " << v << ", 2^" << k;
  }
}

// Mixed magnitudes within the span: tiny and huge coordinates in one input, crossing
// segments among them, refined a little too.
TEST(ExtremeInputs, MixedMagnitudesWithinTheSpan) {
  std::mt19937_64 rng(11);
  for (int round = 0; round < 20; ++round) {
    Pslg in;
    const int spread = 10 + 6 * round;  // exponents of the coordinates spread over this many
    std::uniform_int_distribution<int> exponent(-spread / 2, spread / 2);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 30; ++i) in.points.push_back({std::ldexp(u(rng), exponent(rng)), std::ldexp(u(rng), exponent(rng))});
    for (std::uint32_t i = 0; i + 1 < 20; i += 2) in.segments.push_back({i, i + 1, 1});
    SCOPED_TRACE("round " + std::to_string(round) + ", spread 2^" + std::to_string(spread));
    triangulate_everywhere(in, true);
    RefineOptions o = options_for(*find_algorithm("offcenter"));
    o.criteria.min_angle_deg = 20;
    o.criteria.max_steiner = 300;
    o.triangulate.convex_hull = true;
    const TriMesh m = refine(in, o);
    const CheckReport check = check_mesh(m, &in);
    EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems.front());
  }
}

// Beyond the span the input is refused by rule, naming both coordinates; nothing breaks.
TEST(ExtremeInputs, CoordinatesTooFarApartAreRefusedByName) {
  const std::string huge = refusal(with_segments(
      {{0.0, 1.1e308}, {0.2003, 0.0}, {3.0, 0.0}, {0.35, 0.0}, {0.3002, 0.0}, {0.2003, 1.0}}, {}));
  EXPECT_NE(huge.find("too far apart in magnitude"), std::string::npos) << huge;
  EXPECT_NE(huge.find("vertex 0 (0, 1.1e+308)"), std::string::npos) << huge;
  const std::string subnormal = refusal(with_segments({{0, 0}, {1, 0}, {0, 1}, {5e-324, 0.5}}, {}));
  EXPECT_NE(subnormal.find("5e-324 of vertex 3 (5e-324, 0.5) is more than 2^140"), std::string::npos) << subnormal;
  EXPECT_NE(subnormal.find("times smaller than 1 of vertex 1 (1, 0)"), std::string::npos) << subnormal;
  // Both in one vertex: the message names the two coordinates, and the vertex once.
  const std::string one = refusal(with_segments({{0, 0}, {0.5, 0}, {0, 0.5}, {5e-324, 1}}, {}));
  EXPECT_NE(one.find("5e-324 is more than 2^140 (about 1e42) times smaller than 1 of vertex 3 (5e-324, 1)"),
            std::string::npos) << one;
  Pslg hole = with_segments({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {1, 2}, {2, 0}});
  hole.holes.push_back({1e-60, 0.25});
  EXPECT_NE(refusal(hole).find("hole point 0"), std::string::npos) << refusal(hole);
  // At the span's edge: accepted and valid.
  triangulate_everywhere(with_segments({{0, 0}, {1, 0}, {0, 1}, {std::ldexp(1.0, -140), 0.5}, {1, 1}}, {{3, 4}}), true);
}

// Constructions keep to the rule too: two unit-sized segments crossing among a coordinate
// of 4e41 (within the span by itself) cross at a point 2^140 below it. The input is refused,
// where before the mesh was written and then refused by the checker (a fuzzing finding).
TEST(ExtremeInputs, ACrossingBeyondTheSpanIsRefusedByTheRule) {
  const Pslg in = with_segments({{0, 0}, {1, 5}, {1, 0}, {0, 1}, {0.35, 4e41}, {1, 0}}, {{0, 1}, {2, 3}, {0, 5}});
  EXPECT_NE(refusal(in).find("two segments cross at a point with a nonzero coordinate more than 2^140"),
            std::string::npos) << refusal(in);
  // The same crossing among unit coordinates is fine.
  const Pslg unit = with_segments({{0, 0}, {1, 5}, {1, 0}, {0, 1}, {0.35, 4}, {1, 0}}, {{0, 1}, {2, 3}, {0, 5}});
  triangulate_everywhere(unit, false);
}

}  // namespace
}  // namespace meshstep
