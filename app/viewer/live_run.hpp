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
  // Any command that records LOG: ARGS, the program first. With no `backend` there is no
  // preview (the workbench keeps its last mesh on screen meanwhile: workbench_host.hpp).
  // What the program prints goes to a file of its own (output()).
  LiveRun(std::vector<std::string> args, std::string input, std::string log, const std::string& backend);
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
  // What it printed (its --stats json line, when asked for).
  std::string output() const;
  // The processor time it used, user and system, once it has ended (0 before).
  double cpu_seconds() const { return cpu_seconds_; }

  // The mesh of the run so far (CanvasWorker following LOG.partial); only with a backend.
  bool has_preview() const { return preview_ != nullptr; }

  CanvasWorker& preview() { return *preview_; }

 private:
  std::string input_, log_, command_, messages_file_, output_file_;
  double cpu_seconds_ = 0.0;
  pid_t pid_ = -1;
  bool done_ = false, cancelled_ = false;
  int status_ = -1;
  std::chrono::steady_clock::time_point started_, ended_;
  std::unique_ptr<CanvasWorker> preview_;
};

}  // namespace meshstep::viewer
