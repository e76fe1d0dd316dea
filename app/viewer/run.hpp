// The viewer's main loop: a host (window or off screen), the viewer's frames, and a script
// of actions when one is given.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "script.hpp"
#include "session.hpp"

namespace meshstep::viewer {

struct RunOptions {
  int width = 1280, height = 800;
  bool offscreen = false;   // no window: EGL or OSMesa (`gl`)
  std::string gl = "auto";
  std::vector<ScriptAction> script;
  std::string script_path;  // for messages
  bool quiet = false;
};

// Runs until the window closes, Ctrl+Q, or (off screen) the script ends. Returns the exit
// status; throws InputError for a script action that cannot be done (a file not written).
int run_viewer(std::unique_ptr<Session> session, const RunOptions& options);

}  // namespace meshstep::viewer
