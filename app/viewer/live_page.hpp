// The window while a live run goes: the command, the time it has run, the mesh written so
// far (drawn by the run's preview worker a few times a second) and a Cancel button (Esc).
// The frames stay short whatever the run's size: the run is another process, the reading
// and drawing another thread.
#pragma once

#include <memory>
#include <string>

#include "canvas_worker.hpp"
#include "live_run.hpp"
#include "log_opening.hpp"
#include "picture_texture.hpp"

namespace meshstep::viewer {

struct LiveView {
  explicit LiveView(std::unique_ptr<LiveRun> r) : run(std::move(r)) {}
  std::unique_ptr<LiveRun> run;
  CanvasPicture picture;  // the latest drawn
  PictureTexture texture;
  bool has_picture = false;
  std::size_t pictures = 0;
  // The ended run's log, opened off the window's thread (a 1e6-point log takes a second or
  // more); the page stays, its last picture on the canvas, until the log is open.
  std::unique_ptr<LogOpening> opening;
};

// Draws the page over the whole window (between ImGui::NewFrame and ImGui::Render).
void draw_live_page(LiveView& live, int width, int height);

// Its state for scripts (`peek`): {"page": "live", "running": ..., ...}.
std::string live_state_json(LiveView& live);

}  // namespace meshstep::viewer
