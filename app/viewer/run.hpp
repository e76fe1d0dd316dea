// The viewer's main loop: a host (window or off screen), the viewer's frames, and a script
// of actions when one is given.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "open_input.hpp"
#include "script.hpp"
#include "session.hpp"
#include "settings.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

struct RunOptions {
  int width = 1280, height = 800;
  bool offscreen = false;   // no window: EGL or OSMesa (`gl`)
  std::string gl = "auto";
  std::vector<ScriptAction> script;
  std::string script_path;  // for messages
  bool quiet = false;
  // Where to write one line per frame: its index, milliseconds from the program's start to
  // the frame's end, the frame's own milliseconds, its allocations, the cursor's position,
  // the position the canvas shows (-1: nothing yet), 1 when a live run went during the frame
  // (else 0); the responsiveness benchmark and the tests read it.
  std::string frame_log;
  // An input to run live at the start (.poly, .node), with its refinement; the log opens
  // when the run ends, at this step or event (-1: the end).
  std::string live_input;
  RefineOptions live_refine;
  std::int64_t start_step = -1, start_event = -1;
  // Two to four logs side by side (compare_view.hpp), in the command line's order; the
  // session given to run_viewer is then null. start_step / start_event place the leader.
  std::vector<std::string> side_by_side;
  // Who draws the canvas (viewer.hpp): automatic, this thread or a worker.
  CanvasMode canvas = CanvasMode::automatic;
  // The UI scale to start at (--ui-scale; 0: the settings', else 1).
  float ui_scale = 0.0f;
  // Options to start from and to keep (nullptr: the defaults, nothing kept: scripts).
  Settings* settings = nullptr;
  // A guided tour to play (`--tour`), resolved against the session's log: the first viewer
  // shown plays it from its first stop.
  std::shared_ptr<TourGuide> tour;
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
};

// Runs until the window closes, Ctrl+Q, or (off screen) the script ends. Without a session
// it starts on the start page (examples and recent files). Files dropped on the window or
// picked on the start page are opened with `opener`. Returns the exit status; throws
// InputError for a script action that cannot be done (a file not written).
int run_viewer(std::unique_ptr<Session> session, const RunOptions& options, Opener& opener);

}  // namespace meshstep::viewer
