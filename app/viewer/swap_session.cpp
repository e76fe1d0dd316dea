// Viewer::swap_session: the workbench's next run shown in the viewer that showed the last
// one. A new Viewer per edit made its renderer again (shaders compiled, the font atlas
// rasterised): timed under load, making it and its first canvas cost two to three idle
// frames on llvmpipe, more than the re-meshing of a 1,000-vertex input. What the viewer
// keeps from the run it showed is forgotten here, as a new viewer would not have it; what
// belongs to the person (the options, the panels shown or hidden, full screen, the camera
// unless fitted again) stays: a new viewer per edit also showed the panels again after Tab.
#include "compare_view.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

bool Viewer::swap_session(std::unique_ptr<Session>& next) {
  // A canvas worker (a big run) or runs side by side: their threads and canvases belong to
  // the run shown; the caller makes a new viewer for those.
  const replay::LogReader* log = next->log();
  if (worker_ || compare_ || (log && log->vertices().size() > kCanvasWorkerVertices)) return false;
  // The options the person set live in the session: carried as a new viewer's are (capture,
  // then apply, as the run's loop does from one viewer to the next).
  Settings kept;
  capture(kept);
  // A tour or a quiz was of the old run.
  if (quiz_) stop_quiz();
  tour_.reset();
  // The jobs read the old log on their threads: stopped before it goes.
  invariants_.reset();
  history_.reset();
  plots_.reset();
  timeline_cache_ = TimelineCache{};
  session_ = std::move(next);
  view3d_ = View3d(session_->log());
  angle_bound_ = log ? log->run().min_angle.value_or(0.0) : 0.0;

  // Every cache keyed by the session's scene builds starts again: the new session counts
  // its builds from zero, and the same count would name another picture.
  drawn_ = Drawn{};
  stats_of_build_ = SIZE_MAX;
  hover_edges_.clear();
  hover_edges_build_ = SIZE_MAX;
  code_ = {};
  code_position_ = UINT64_MAX;
  // The selection named elements of the old run.
  hovered_ = {};
  selected_ = {};
  selected_vertices_ = {};
  lepp_ = {};
  selection_build_ = SIZE_MAX;
  selection_text_.clear();
  story_ = {};
  story_of_ = {{}, UINT64_MAX, false};
  selection_text_of_ = {{}, SIZE_MAX};
  goto_refusal_.clear();
  plot_scales_known_ = false;
  invariants_text_.clear();
  notice_.clear();
  notice_seconds_ = 0.0;
  fit_box_.reset();
  // Fitted to the new run on the next frame, unless the caller keeps the camera.
  fit_pending_ = true;
  camera_moved_ = false;
  keep_corner_ = false;
  camera_2d_ = {};
  moved_2d_ = false;
  picture_in_3d_ = false;
  background_started_ = false;
  apply(kept);
  // The history's index and the plots of the new log, as a new viewer starts them. (Started
  // a frame later, their first frame drawn ready, which allocates, fell on an idle frame.)
  if (log) start_background_jobs();
  return true;
}

Viewer::Leftovers Viewer::release_run() {
  invariants_.reset();
  history_.reset();
  plots_.reset();
  Leftovers out;
  out.worker = std::move(worker_);
  out.session = std::move(session_);
  return out;
}

}  // namespace meshstep::viewer
