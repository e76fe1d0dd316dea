// "Why this point?": the current step of a run in words, a line per thing it did, for the
// viewer's explain panel (the caption says it in one line; this says it in full).
//
//   step 57 of 124 · refine
//   bad triangle 12 40 7: smallest angle 21.3° < 30°
//   chosen: the off-center (3.25, 1.5); also considered: the circumcenter (3.4, 1.62)
//   rejected: it encroaches segment 4-9 (inside its diametral circle)
//   segment 4-9 split on a concentric shell (vertex 88), so no shorter segment pieces appear
//   went in by 4 flips: 12-40 → 7-88, ...
//   new triangles: 6, smallest angle 31.2°, largest 98.4°
#pragma once

#include <string>
#include <vector>

#include "meshstep/replay/replay.hpp"

namespace meshstep::scene {

struct Explanation {
  std::string heading;             // "step 57 of 124 · refine", "before the run"
  std::vector<std::string> lines;  // what the step did, in the order it did it
};

// The explanation of the step the cursor's last event belongs to, up to the cursor (the
// same events the scene's overlays draw).
Explanation explain_step(const replay::Replay& cursor);

}  // namespace meshstep::scene
