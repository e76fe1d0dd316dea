// The 3D view's model (view_3d.hpp) and the inspector in 3D, in process on a recorded
// terrain run: the orbit's ranges, the turn about the pivot, the lifted scene made again
// only when the moment or the orbit changes, the front triangle picked on the picture, and
// the inspector's Lepp path measured in 3D as the run measured it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "golden_runs.hpp"
#include "inspector.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/lift.hpp"
#include "golden_runs.hpp"
#include "view_3d.hpp"

namespace meshstep::viewer {
namespace {

using replay::Event;
using replay::EventType;

constexpr const char* kLeppSurface = "--max-error 1";

scene::Scene moment(const replay::LogReader& log, std::uint64_t step) {
  replay::Replay cursor(log);
  cursor.seek_step(step);
  return scene::build_scene(cursor, {});
}

TEST(View3dOrbit, AnglesWrapAndClampAndTheScaleStaysPositive) {
  EXPECT_EQ(normalized({190.0, 35.0, 1.0}).azimuth_deg, -170.0);
  EXPECT_EQ(normalized({-180.0, 35.0, 1.0}).azimuth_deg, 180.0);
  EXPECT_EQ(normalized({-540.0, 35.0, 1.0}).azimuth_deg, 180.0);
  EXPECT_EQ(normalized({0.0, 120.0, 1.0}).elevation_deg, 90.0);
  EXPECT_EQ(normalized({0.0, -91.0, 1.0}).elevation_deg, -90.0);
  EXPECT_EQ(normalized({0.0, 0.0, 0.0}).z_scale, 1.0);  // not a scale: the default
  EXPECT_EQ(normalized({0.0, 0.0, 1e9}).z_scale, Orbit::kMaxZScale);
  EXPECT_EQ(normalized({NAN, NAN, NAN}), Orbit{});
}

TEST(View3dOrbit, ARunWithoutHeightsHasNoThirdDimension) {
  const replay::LogReader* planar = golden::lesson_run("--min-angle 30");
  ASSERT_TRUE(planar);
  View3d view(planar);
  EXPECT_FALSE(view.available());
  EXPECT_FALSE(view.set_on(true));
  EXPECT_FALSE(view.on());
  EXPECT_TRUE(view.heights().empty());
  EXPECT_FALSE(View3d(nullptr).available());

  const replay::LogReader* terrain = golden::terrain_run(kLeppSurface);
  ASSERT_TRUE(terrain);
  View3d lifted(terrain);
  EXPECT_TRUE(lifted.available());
  EXPECT_TRUE(lifted.set_on(true));
  EXPECT_EQ(lifted.heights().size(), terrain->vertices().size());
}

// The lifted scene is lift_scene's, made once per moment and orbit; its points are where
// screen_points() says the vertices are.
TEST(View3dScene, LiftsOncePerMomentAndOrbit) {
  const replay::LogReader* log = golden::terrain_run(kLeppSurface);
  ASSERT_TRUE(log);
  View3d view(log);
  const scene::Scene planar = moment(*log, 40);
  const scene::Scene expected = scene::lift_scene(planar, view.heights(), view.orbit().view());
  const scene::Scene& lifted = view.lifted(planar, 7, SIZE_MAX);
  EXPECT_EQ(lifted.mesh.points, expected.mesh.points);
  EXPECT_EQ(lifted.mesh.triangles, expected.mesh.triangles);
  EXPECT_EQ(lifted.caption, expected.caption);
  EXPECT_NE(lifted.caption.find("3D -60\u00B0, 35\u00B0"), std::string::npos) << lifted.caption;
  // Every vertex of the run, on screen as the lifted scene has it.
  ASSERT_EQ(view.screen_points().size(), lifted.mesh.points.size());
  for (std::size_t v = 0; v < lifted.mesh.points.size(); ++v)
    EXPECT_EQ(view.screen_points()[v], lifted.mesh.points[v]) << "vertex " << v;

  // The same moment and orbit: the same scene, not lifted again (a caption changed by hand
  // stays); a new orbit or a new moment: lifted again.
  view.lifted(planar, 7, SIZE_MAX).caption = "kept";
  EXPECT_EQ(view.lifted(planar, 7, SIZE_MAX).caption, "kept");
  EXPECT_TRUE(view.turn(30.0, 0.0));
  EXPECT_NE(view.lifted(planar, 7, SIZE_MAX).caption, "kept");
  view.lifted(planar, 7, SIZE_MAX).caption = "kept";
  EXPECT_NE(view.lifted(planar, 8, SIZE_MAX).caption, "kept");
  EXPECT_FALSE(view.turn(0.0, 0.0)) << "no change, no new lift";

  // Vertex markers: kept up to the number asked for, all left out above it.
  const auto markers = [](const scene::Scene& s) {
    std::size_t n = 0;
    for (const scene::Shape& shape : s.shapes) n += shape.layer == scene::Layer::vertices ? shape.points.size() : 0;
    return n;
  };
  const std::size_t all = markers(view.lifted(planar, 8, SIZE_MAX));
  EXPECT_GT(all, 40u);
  EXPECT_EQ(markers(view.lifted(planar, 8, all)), all);
  EXPECT_EQ(markers(view.lifted(planar, 8, all - 1)), 0u);
  EXPECT_EQ(max_vertex_markers_for(1280, 720), 1024u);
}

// Zoomed in, a turn keeps the pivot under the camera's centre: the point looked at stays in
// the middle of the picture, seen from the new side.
TEST(View3dCamera, TurnsAboutThePointLookedAt) {
  const replay::LogReader* log = golden::terrain_run(kLeppSurface);
  ASSERT_TRUE(log);
  View3d view(log);
  ASSERT_TRUE(view.set_on(true));
  const BBox box = view.run_box();
  ASSERT_FALSE(box.empty());
  scene::Camera camera = scene::Camera::fit(box, 800, 600, 0.0);
  view.center_pivot();
  view.aim(camera);
  EXPECT_NEAR(view.pivot_on_screen().x, camera.center().x, 1e-9);
  EXPECT_NEAR(view.pivot_on_screen().y, camera.center().y, 1e-9);

  // Zoom onto a vertex (off the middle) and aim there: the vertex is the pivot's place on screen.
  const std::size_t v = log->vertices().size() / 3;
  camera = scene::Camera(view.screen_points()[v], 4.0 * camera.pixels_per_unit(), 800, 600);
  view.aim(camera);
  // Turn: the vertex moves on screen, the pivot turns with the view; a vertex at the pivot's
  // depth would stay at the pivot exactly, and this one, near it, stays near.
  const Point before = view.screen_points()[v];
  ASSERT_TRUE(view.turn(40.0, 20.0));
  const Point after = view.screen_points()[v];
  EXPECT_GT(std::hypot(after.x - before.x, after.y - before.y), 1.0) << "the vertex moved on the plane";
  const Point pivot = view.pivot_on_screen();
  const double span = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
  EXPECT_LT(std::hypot(after.x - pivot.x, after.y - pivot.y), 0.2 * span) << "and stayed near the middle";
  // A whole turn more, in two halves: the pivot is back where it was on screen.
  ASSERT_TRUE(view.turn(180.0, 0.0));
  ASSERT_TRUE(view.turn(180.0, 0.0));
  EXPECT_NEAR(view.pivot_on_screen().x, pivot.x, 1e-6);
  EXPECT_NEAR(view.pivot_on_screen().y, pivot.y, 1e-6);
  // The heights' scale: the pivot keeps its place in space (its height scaled with the rest).
  const Point3 before_scale{pivot.x, pivot.y, 0.0};
  ASSERT_TRUE(view.scale_heights(3.0));
  ASSERT_TRUE(view.scale_heights(1.0 / 3.0));
  EXPECT_NEAR(view.pivot_on_screen().x, before_scale.x, 1e-9);
  EXPECT_NEAR(view.pivot_on_screen().y, before_scale.y, 1e-9);
}

// On the picture, a point covered by several triangles (seen from low, the far slope behind
// the near one) picks the nearest: the last drawn, back to front. Every triangle's centroid
// on screen picks itself unless a nearer triangle covers it.
TEST(InspectorPick3d, PicksTheFrontTriangleOnThePicture) {
  const replay::LogReader* log = golden::terrain_run(kLeppSurface);
  ASSERT_TRUE(log);
  View3d view(log);
  ASSERT_TRUE(view.set_orbit({-60.0, 10.0, 4.0}));  // from low, heights stretched: slopes hide slopes
  const scene::Scene planar = moment(*log, log->step_count());
  const scene::Scene& lifted = view.lifted(planar, 1, SIZE_MAX);
  const auto& shown = lifted.mesh;
  std::size_t hidden = 0;
  for (std::uint32_t t = 0; t < shown.triangles.size(); ++t) {
    const auto& v = shown.triangles[t];
    const Point c{(shown.points[v[0]].x + shown.points[v[1]].x + shown.points[v[2]].x) / 3.0,
                  (shown.points[v[0]].y + shown.points[v[1]].y + shown.points[v[2]].y) / 3.0};
    const Picked picked = pick_front(shown, c, 0.0);
    ASSERT_EQ(picked.kind, Picked::Kind::triangle) << "triangle " << t;
    EXPECT_GE(picked.index, t) << "never one drawn before it";
    hidden += picked.index != t;
    // The planar triangle of the same vertices is the one the inspector names.
    const std::uint32_t same = find_triangle(planar.mesh, shown.triangles[picked.index]);
    ASSERT_NE(same, kNoIndex);
  }
  EXPECT_GT(hidden, 0u) << "seen from 10 degrees, some slope hides another";
  EXPECT_LT(hidden, shown.triangles.size()) << "and some triangle is in front";
  // Near a vertex: the vertex; off the picture: nothing.
  const std::uint32_t corner = shown.triangles.back()[0];
  const Point at = shown.points[corner];
  EXPECT_EQ(pick_front(shown, {at.x + 1e-3, at.y}, 1.0).kind, Picked::Kind::vertex);
  EXPECT_EQ(pick_front(shown, {1e9, 1e9}, 1.0).kind, Picked::Kind::none);
}

// The inspector's Lepp path of each step's worst triangle, measured with the run's heights,
// is the path the run recorded (its lepp_path event): the same triangles to the same
// terminal edge. In the plane it is not, at some step.
TEST(InspectorLepp3d, IsThePathLeppSurfaceFollowed) {
  const replay::LogReader* log = golden::terrain_run(kLeppSurface);
  ASSERT_TRUE(log);
  View3d view(log);
  std::size_t checked = 0, planar_differs = 0;
  for (std::uint64_t k = 0; k < log->step_count(); ++k) {
    if (log->step_kind(k) != replay::StepKind::refine) continue;
    const std::uint64_t begin = log->step_start(k);
    const Event test = log->event(begin + 1);
    ASSERT_EQ(test.type, EventType::criterion_test);
    const std::array<std::uint32_t, 3> worst{test.ids[0], test.ids[1], test.ids[2]};
    const Event path = log->event(begin + 2);
    ASSERT_EQ(path.type, EventType::lepp_path);
    const std::vector<std::uint32_t> recorded(path.list.begin(), path.list.end());
    const std::array<std::uint32_t, 2> terminal{path.ids[0], path.ids[1]};

    replay::Replay cursor(*log);
    cursor.seek_event(begin);  // the mesh the step started from
    const scene::Scene planar = scene::build_scene(cursor, {});
    const std::uint32_t t = find_triangle(planar.mesh, worst);
    ASSERT_NE(t, kNoIndex) << "step " << k + 1;
    const LeppPath lepp = lepp_path(planar.mesh, t, view.heights());
    ASSERT_EQ(lepp.triangles.size() * 3, recorded.size()) << "step " << k + 1;
    for (std::size_t i = 0; i < lepp.triangles.size(); ++i) {
      std::array<std::uint32_t, 3> mine = planar.mesh.triangles[lepp.triangles[i]], theirs{};
      std::copy_n(recorded.begin() + static_cast<std::ptrdiff_t>(3 * i), 3, theirs.begin());
      std::sort(mine.begin(), mine.end());
      std::sort(theirs.begin(), theirs.end());
      EXPECT_EQ(mine, theirs) << "step " << k + 1 << ", triangle " << i;
    }
    EXPECT_EQ(std::minmax(lepp.a, lepp.b), std::minmax(terminal[0], terminal[1])) << "step " << k + 1;
    EXPECT_EQ(lepp.boundary, path.ids[2] == 1) << "step " << k + 1;
    const LeppPath flat = lepp_path(planar.mesh, t);
    planar_differs += flat.triangles != lepp.triangles;
    ++checked;
  }
  EXPECT_GT(checked, 100u);
  EXPECT_GT(planar_differs, 0u) << "the heights never mattered: the test shows nothing";
}

}  // namespace
}  // namespace meshstep::viewer
