// One numbering of a run's steps, for every command and the viewer.
//
// Step K names a moment: the mesh after K steps. Step 0 is before the first step (after the
// preamble), and a run of n steps has the moments 0..n; step K is also the name of the work
// that takes moment K - 1 to moment K. `render --step K`, `export --from/--to`, `log mesh
// --step K`, `log check`, `log dump`, `explain` and the viewer all use it, and all refuse a
// number outside 0..n in the words step_refusal() writes.
#pragma once

#include <cstdint>
#include <string>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::replay {

// The refusal for `option K` ("--step", "--from"...) when K is not a step of the run, or ""
// when it is. `end_allowed`: -1 stands for the end (the last moment, events after it too).
std::string step_refusal(const LogReader& log, const std::string& option, std::int64_t k, bool end_allowed = true);

// The replay position of moment K (K in 0..n): the start of the (K+1)-th step's events, or
// the end of the log for K = n.
std::uint64_t step_position(const LogReader& log, std::uint64_t k);

// The step that a replay position shows: K at moment K; inside the work of step K (some of
// its events applied, not all) also K, with `within` set. 0 before the first step.
struct StepAt {
  std::uint64_t step = 0;
  bool within = false;
};
StepAt step_at(const LogReader& log, std::uint64_t position);

// The step that event e belongs to, as step_at numbers it: 1..n for a step's events, 0 for
// the preamble's.
std::uint64_t step_of_event_numbered(const LogReader& log, std::uint64_t e);

}  // namespace meshstep::replay
