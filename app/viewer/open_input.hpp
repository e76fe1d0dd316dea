// Opening what the viewer shows: a replay log; a mesh PREFIX; or a .poly/.node input, which
// is triangulated (and refined, when refinement options are given) by the meshstep program
// beside the viewer, recording the run into a temporary log that is then opened.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "session.hpp"

namespace meshstep::viewer {

class LiveRun;

// Whether the viewer opens this path as an input to triangulate (.poly, .node).
bool is_input(const std::string& path);

struct RefineOptions {
  std::string algorithm, min_angle, max_angle, max_area, max_aspect;
  bool any() const {
    return !algorithm.empty() || !min_angle.empty() || !max_angle.empty() || !max_area.empty() || !max_aspect.empty();
  }
};

// Owns the temporary logs of recorded inputs and removes them when it goes.
class Opener {
 public:
  explicit Opener(bool quiet) : quiet_(quiet) {}
  ~Opener();
  Opener(const Opener&) = delete;
  Opener& operator=(const Opener&) = delete;

  // Throws InputError ("FILE: what is wrong") when it cannot be opened or its run fails.
  // An input is recorded first, the window waiting (a live run does not wait: start_live).
  std::unique_ptr<Session> open(const std::string& path, const RefineOptions& refine = {});
  // Starts the run of an input (.poly, .node) that the window watches as it goes; its log
  // is a temporary one, removed with the opener.
  std::unique_ptr<LiveRun> start_live(const std::string& input, const RefineOptions& refine, const std::string& backend);

 private:
  std::string record_run(const std::string& input, const RefineOptions& refine);
  std::string temporary_log();

  bool quiet_;
  std::vector<std::string> temporary_logs_;
};

// The bundled examples (assets/examples/*.poly) with their first comment line, for the
// start page; empty when the folder is not found.
struct Example {
  std::string path, description;
};
std::vector<Example> bundled_examples();

}  // namespace meshstep::viewer
