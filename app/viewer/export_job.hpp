// Export from the viewer: pictures of the canvas (PNG through the renderer, or SVG) and of
// the whole window, written beside the log; and an animation of a range of steps, made by
// `meshstep export` in a process of its own so that the window keeps drawing.
#pragma once

#include <sys/types.h>

#include <string>

namespace meshstep::viewer {

// "run_step45.png" beside "run.mslog" (or in the current folder for a run without a file).
std::string export_name(const std::string& log_path, unsigned long long step, const char* what, const char* extension);

class ExportJob {
 public:
  // `meshstep`: the program that exports (default: the one beside this program).
  explicit ExportJob(std::string meshstep = "");
  ~ExportJob();
  // Runs `meshstep export LOG --video OUT --every step --from A --to B`; false (and why in
  // status()) when it cannot start.
  bool start(const std::string& log, const std::string& out, unsigned long long from, unsigned long long to);
  bool running();
  // "writing run_steps_10-40.mp4...", "wrote run_steps_10-40.mp4", "failed: ...".
  const std::string& status() const { return status_; }

 private:
  std::string meshstep_;
  pid_t pid_ = -1;
  std::string out_, status_;
};

}  // namespace meshstep::viewer
