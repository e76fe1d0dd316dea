// Opening what the viewer shows: a replay log; a mesh PREFIX; or a .poly/.node input, which
// is triangulated (and refined, when refinement options are given) by the meshstep program
// beside the viewer, recording the run into a temporary log that is then opened.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "meshstep/refine/run_spec.hpp"

#include "session.hpp"

namespace meshstep::viewer {

class LiveRun;

// Whether the viewer opens this path as an input to triangulate (.poly, .node).
bool is_input(const std::string& path);

// What an input's live run does: triangulate it, or refine it as `meshstep refine` takes
// the operation's words (refine/run_spec.hpp).
struct RefineOptions {
  std::optional<Operation> operation;  // none: triangulate only
  std::string max_memory;  // refine's --max-memory (its default budget when empty); not a bound
  bool any() const { return operation.has_value(); }
};

// Owns the temporary logs of recorded inputs and removes them when it goes.
class Opener {
 public:
  Opener() = default;
  ~Opener();
  Opener(const Opener&) = delete;
  Opener& operator=(const Opener&) = delete;

  // A log or a mesh PREFIX (an input given here is shown as it is, not run: inputs run
  // live, through start_live). Throws InputError ("FILE: what is wrong").
  std::unique_ptr<Session> open(const std::string& path);
  // Starts the run of an input (.poly, .node) that the window watches as it goes; its log
  // is a temporary one, removed with the opener.
  std::unique_ptr<LiveRun> start_live(const std::string& input, const RefineOptions& refine, const std::string& backend);

 private:
  std::string temporary_log();

  std::vector<std::string> temporary_logs_;
};

// The bundled examples (assets/examples/*.poly) with their first comment line, for the
// start page; empty when the folder is not found.
struct Example {
  std::string path, description;
};
std::vector<Example> bundled_examples();

}  // namespace meshstep::viewer
