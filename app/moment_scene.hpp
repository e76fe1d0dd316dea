// The scene of a source at a moment: a log at a replay position, or a mesh or an input as
// they are. Shared by render (one picture) and export (many).
#pragma once

#include "draw_options.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/build.hpp"
#include "scene_source.hpp"

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

}  // namespace meshstep::app
