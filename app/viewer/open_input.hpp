// Opening what the viewer shows: a replay log; a mesh PREFIX; or a .poly/.node input, which
// is triangulated (and refined, when refinement options are given) by the meshstep program
// beside the viewer, recording the run into a temporary log that is then opened.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "session.hpp"

namespace meshstep::viewer {

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
  std::unique_ptr<Session> open(const std::string& path, const RefineOptions& refine = {});

 private:
  std::string record_run(const std::string& input, const RefineOptions& refine);

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
