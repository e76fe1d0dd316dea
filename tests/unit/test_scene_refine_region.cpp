// The region a refinement is limited to is drawn as a dashed outline: on a run of one
// operation (--region) at every moment, and on a recipe's log while the operation that has
// it runs, not before.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/operations.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/build.hpp"
#include "run_cli.hpp"
#include "scene_at_step.hpp"

namespace meshstep {
namespace {

using scene::Scene;
using testing::scene_at_step;

constexpr const char* kSquare =
    "4 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n"
    "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
    "0\n";

class SceneRefineRegion : public testing::CliTest {
 protected:
  SceneRefineRegion() : CliTest("meshstep_region_scene_") {}
};

// The outline's corners, each once, sorted.
std::vector<Point> corners(const scene::Shape& s) {
  std::vector<Point> out(s.points.begin(), s.points.end());
  std::sort(out.begin(), out.end(), [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

TEST_F(SceneRefineRegion, ARunLimitedToABoxShowsTheBoxThroughout) {
  const std::string input = write("square.poly", kSquare), log_path = file("box.mslog");
  const testing::CommandResult r = meshstep("refine " + input + " --max-area 0.5 --region 1,2,4,6 -q -o " +
                                            file("box") + " --record " + log_path);
  ASSERT_EQ(r.status, 0) << r.err;
  const replay::LogReader log(log_path);
  const std::uint64_t last = log.step_count();
  for (const std::uint64_t step : {std::uint64_t{0}, last / 2, last}) {
    const Scene s = scene_at_step(log, step);
    const scene::Shape* outline = s.find("refine_region");
    ASSERT_NE(outline, nullptr) << "step " << step;
    EXPECT_TRUE(outline->dashed);
    EXPECT_EQ(outline->points.size(), 8u);  // four sides, two ends each
    EXPECT_EQ(corners(*outline), (std::vector<Point>{{1, 2}, {1, 6}, {4, 2}, {4, 6}})) << "step " << step;
  }

  // Without a region, no outline.
  const std::string whole = file("whole.mslog");
  ASSERT_EQ(meshstep("refine " + input + " --max-area 0.5 -q -o " + file("whole") + " --record " + whole).status, 0);
  const replay::LogReader plain(whole);
  EXPECT_EQ(scene_at_step(plain, plain.step_count()).find("refine_region"), nullptr);
}

TEST_F(SceneRefineRegion, ARecipeShowsARegionOnlyWhileItsOperationRuns) {
  const std::string input = write("square.poly", kSquare), log_path = file("chain.mslog");
  const std::string recipe = write("chain.recipe",
                                   "refine --algorithm lepp-centroid --min-angle 25 --max-area 4\n"
                                   "refine --max-area 0.2 --region 5,5,9,9\n");
  const testing::CommandResult r =
      meshstep("run " + recipe + " " + input + " -q -o " + file("chain") + " --record " + log_path);
  ASSERT_EQ(r.status, 0) << r.err;
  const replay::LogReader log(log_path);
  const std::vector<replay::OperationSpan> spans = replay::operation_spans(log, log_path);
  ASSERT_EQ(spans.size(), 2u);
  ASSERT_LT(spans[1].from_step + 1, spans[1].to_step);
  EXPECT_EQ(scene_at_step(log, spans[0].to_step - 1).find("refine_region"), nullptr) << "the first operation has none";
  const Scene during = scene_at_step(log, spans[1].from_step + 1);
  const scene::Shape* outline = during.find("refine_region");
  ASSERT_NE(outline, nullptr);
  EXPECT_EQ(corners(*outline), (std::vector<Point>{{5, 5}, {5, 9}, {9, 5}, {9, 9}}));
}

// A recipe's polygon written out (--region-polygon, what the viewer's lasso saves): the
// outline is that polygon, edge by edge, while its operation runs.
TEST_F(SceneRefineRegion, ARecipesInlinePolygonIsDrawnEdgeByEdge) {
  const std::string input = write("square.poly", kSquare), log_path = file("lasso.mslog");
  const std::string recipe = write("lasso.recipe",
                                   "refine --algorithm lepp-centroid --min-angle 25 --max-area 4\n"
                                   "refine --max-area 0.2 --region-polygon 2,2,8,3,6,5,7,8,3,7\n");
  const testing::CommandResult r =
      meshstep("run " + recipe + " " + input + " -q -o " + file("lasso") + " --record " + log_path);
  ASSERT_EQ(r.status, 0) << r.err;
  const replay::LogReader log(log_path);
  const std::vector<replay::OperationSpan> spans = replay::operation_spans(log, log_path);
  ASSERT_EQ(spans.size(), 2u);
  ASSERT_LT(spans[1].from_step + 1, spans[1].to_step);
  EXPECT_EQ(scene_at_step(log, spans[0].to_step - 1).find("refine_region"), nullptr);
  const Scene during = scene_at_step(log, spans[1].from_step + 1);
  const scene::Shape* outline = during.find("refine_region");
  ASSERT_NE(outline, nullptr);
  EXPECT_TRUE(outline->dashed);
  // Five edges, counterclockwise as given, each from one vertex to the next (not a box).
  const std::vector<Point> ring{{2, 2}, {8, 3}, {6, 5}, {7, 8}, {3, 7}};
  ASSERT_EQ(outline->points.size(), 10u);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    EXPECT_EQ(outline->points[2 * i], ring[i]) << i;
    EXPECT_EQ(outline->points[2 * i + 1], ring[(i + 1) % ring.size()]) << i;
  }
}


}  // namespace
}  // namespace meshstep
