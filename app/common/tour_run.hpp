// A tour's run, recorded: `meshstep triangulate|refine|run` on the tour's input in a process
// of its own, recording a log that the viewer (`view --tour`) and `export --tour` then read.
// One place says how a tour's run is made, so that both show the same steps.
#pragma once

#include <string>
#include <vector>

#include "meshstep/teach/tour.hpp"

namespace meshstep::app {

// The command line that records the tour's run into `log` (its outputs, for a recipe, under
// `scratch`, a folder that is the caller's to remove): `program` first.
std::vector<std::string> tour_run_arguments(const teach::Tour& tour, const std::string& program, const std::string& log,
                                            const std::string& scratch);

// A folder of its own under the system's temporary folder, removed with everything in it.
class ScratchFolder {
 public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

// Runs `program` for the tour and waits; returns the log's path (in `scratch`). Throws
// InputError("TOUR:LINE: its run failed: ...", the line of its run) when the run fails,
// with what the program said.
std::string record_tour_run(const teach::Tour& tour, const std::string& program, const ScratchFolder& scratch);

}  // namespace meshstep::app
