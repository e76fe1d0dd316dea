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

namespace meshstep::viewer {

struct RunOptions {
  int width = 1280, height = 800;
  bool offscreen = false;   // no window: EGL or OSMesa (`gl`)
  std::string gl = "auto";
  std::vector<ScriptAction> script;
  std::string script_path;  // for messages
  bool quiet = false;
  // Where to write one line per frame: its index, milliseconds from the program's start to
  // the frame's end, the frame's own milliseconds, its allocations, the cursor's position
  // (the responsiveness benchmark and the tests read it).
  std::string frame_log;
  // Options to start from and to keep (nullptr: the defaults, nothing kept: scripts).
  Settings* settings = nullptr;
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
};

// Runs until the window closes, Ctrl+Q, or (off screen) the script ends. Without a session
// it starts on the start page (examples and recent files). Files dropped on the window or
// picked on the start page are opened with `opener`. Returns the exit status; throws
// InputError for a script action that cannot be done (a file not written).
int run_viewer(std::unique_ptr<Session> session, const RunOptions& options, Opener& opener);

}  // namespace meshstep::viewer
