// A run watched as it goes: the meshstep program triangulates (and refines) an input in a
// process of its own, recording its log, while the window keeps drawing. The canvas's
// worker (in its following mode) reads the log's part written so far, a few times a second,
// and draws the mesh at its end; when the run ends, the viewer opens the whole log.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "canvas_worker.hpp"
#include "open_input.hpp"

namespace meshstep::viewer {

// `meshstep triangulate|refine INPUT [refinement options] --record LOG --no-output -q`.
std::vector<std::string> run_arguments(const std::string& input, const RefineOptions& refine, const std::string& log);

class LiveRun {
 public:
  // Starts the run; throws InputError (naming the input) when the program cannot start.
  // `backend`: the GL library of the UI's context, for the preview's worker.
  LiveRun(const std::string& input, const RefineOptions& refine, std::string log, const std::string& backend);
  ~LiveRun();  // stops a run still going
  LiveRun(const LiveRun&) = delete;
  LiveRun& operator=(const LiveRun&) = delete;

  // Looks at the process without waiting: true while it runs.
  bool running();
  bool succeeded() const { return done_ && status_ == 0; }
  // Stops the run (SIGTERM); running() then turns false.
  void cancel();
  bool cancelled() const { return cancelled_; }

  const std::string& input() const { return input_; }
  const std::string& log() const { return log_; }
  // The command as a person would type it, to show.
  const std::string& command() const { return command_; }
  double seconds() const;
  // What the program said on its error stream (its messages are FILE:LINE: ...).
  std::string messages() const;

  // The mesh of the run so far (CanvasWorker following LOG.partial).
  CanvasWorker& preview() { return *preview_; }

 private:
  std::string input_, log_, command_, messages_file_;
  pid_t pid_ = -1;
  bool done_ = false, cancelled_ = false;
  int status_ = -1;
  std::chrono::steady_clock::time_point started_, ended_;
  std::unique_ptr<CanvasWorker> preview_;
};

}  // namespace meshstep::viewer
