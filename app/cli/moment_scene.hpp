// The scene of a source at a moment: a log at a replay position, or a mesh or an input as
// they are. Shared by render (one picture) and export (many).
#pragma once

#include "draw_options.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/lift.hpp"
#include "common/scene_source.hpp"

namespace meshstep::app {

// Follows a log through the moments an export or a render asks for, keeping the face
// ages current only when the picture needs them.
class LogScenes {
 public:
  LogScenes(const replay::LogReader& log, const scene::SceneOptions& options)
      : cursor_(log), options_(options) {}
  scene::Scene at(std::uint64_t position) {
    cursor_.seek_event(position);
    if (options_.color_by != scene::ColorBy::age) return scene::build_scene(cursor_, options_);
    ages_.update(cursor_);
    return scene::build_scene(cursor_, options_, &ages_);
  }
  // The same moment of a terrain's run in 3D (scene/lift.hpp).
  scene::Scene at(std::uint64_t position, const scene::SurfaceView& view) {
    const scene::Scene planar = at(position);
    return scene::lift_scene(planar, scene::mesh_point_heights(planar, cursor_.log()), view);
  }
  const replay::Replay& cursor() const { return cursor_; }

 private:
  replay::Replay cursor_;
  scene::SceneOptions options_;
  scene::FaceAges ages_;
};

// Every point a log's run ever uses: the box an animation keeps still for all its frames.
inline BBox run_bounds(const replay::LogReader& log) {
  BBox box;
  for (const replay::VertexInfo& v : log.vertices())
    if (v.event != kNone) box.add(v.point);
  return box;
}

// Every point of a terrain's run, and the range of its heights.
struct RunBox3d {
  BBox plan;
  double low, high;
};
inline RunBox3d run_box_3d(const replay::LogReader& log) {
  RunBox3d box{run_bounds(log), INFINITY, -INFINITY};
  for (const replay::VertexInfo& v : log.vertices())
    if (v.event != kNone) box.low = std::min(box.low, v.z), box.high = std::max(box.high, v.z);
  return box;
}

// The middle of a terrain's run: a spinning camera turns about it.
inline Point3 run_pivot(const replay::LogReader& log) {
  const RunBox3d box = run_box_3d(log);
  if (box.plan.empty() || !(box.low <= box.high)) return {0.0, 0.0, 0.0};
  return {(box.plan.lo.x + box.plan.hi.x) / 2, (box.plan.lo.y + box.plan.hi.y) / 2, (box.low + box.high) / 2};
}

// The box a 3D animation keeps still: every point of the run, at every height it reaches,
// as each of the views sees it.
inline BBox run_bounds_3d(const replay::LogReader& log, std::span<const scene::SurfaceView> views) {
  const auto [plan, low, high] = run_box_3d(log);
  BBox box;
  if (plan.empty() || !(low <= high)) return box;
  for (const scene::SurfaceView& view : views)
    for (const double x : {plan.lo.x, plan.hi.x})
      for (const double y : {plan.lo.y, plan.hi.y})
        for (const double z : {low, high}) box.add(scene::project({x, y}, z, view));
  return box;
}

}  // namespace meshstep::app
