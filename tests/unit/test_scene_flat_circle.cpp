// Circles of the scene's overlays (a flip's in-circle test, a bad triangle's circumcircle)
// stay within what a picture can draw.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/build.hpp"
#include "run_cli.hpp"
#include "scene_at_step.hpp"

namespace meshstep {
namespace {

using scene::Scene;
using testing::scene_at_step;

std::string asset(const std::string& name) { return std::string(MESHSTEP_ASSETS) + "/examples/" + name; }

class SceneFlatCircle : public testing::CliTest {
 protected:
  SceneFlatCircle() : CliTest("meshstep_flat_circle_") {}
};

// The in-circle test of a triangle a hair from flat (lepp-midpoint on lesson.poly at 28
// degrees, step 40: a flip beside the midpoint just inserted) has a circle of radius 2.5e15
// about a mesh 10 wide: drawn in floats, the ring filled a block of the canvas. A circle that
// big is drawn as the straight line through the triangle, cut to the run's extent; no circle
// of any step is more than a million times the mesh.
TEST_F(SceneFlatCircle, CirclesOfNearlyFlatTrianglesAreDrawnAsLines) {
  const std::string log_path = file("flat.mslog");
  const testing::CommandResult r =
      meshstep("refine " + asset("lesson.poly") + " -a lepp-midpoint --min-angle 28 --no-output -q --record " + log_path);
  ASSERT_EQ(r.status, 0) << r.err;
  const replay::LogReader log(log_path);
  BBox box;
  for (const replay::VertexInfo& v : log.vertices()) box.add(v.point);
  const double extent = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
  std::size_t lines = 0;
  for (std::uint64_t step = 0; step <= log.step_count(); ++step) {
    const Scene s = scene_at_step(log, step);
    for (const scene::Shape& shape : s.shapes) {
      if (shape.role != "flip_circle" && shape.role != "circumcircle") continue;
      if (shape.kind == scene::ShapeKind::circles) {
        for (const double radius : shape.radii) EXPECT_LE(radius, 1e6 * extent) << "step " << step;
      } else {
        ASSERT_EQ(shape.kind, scene::ShapeKind::lines);
        ++lines;
        for (const Point& p : shape.points) {  // within the box grown by a tenth
          EXPECT_GE(p.x, box.lo.x - 0.1 * extent - 1e-9) << "step " << step;
          EXPECT_LE(p.x, box.hi.x + 0.1 * extent + 1e-9) << "step " << step;
          EXPECT_GE(p.y, box.lo.y - 0.1 * extent - 1e-9) << "step " << step;
          EXPECT_LE(p.y, box.hi.y + 0.1 * extent + 1e-9) << "step " << step;
        }
      }
    }
  }
  EXPECT_GT(lines, 0u) << "the run no longer has a flip of a nearly flat triangle: the test needs another";
}

}  // namespace
}  // namespace meshstep
