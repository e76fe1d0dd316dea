// log verify: replay a whole log forward, back to the start and forward again, checking
// every face write against the mesh it applies to, and the replayed mesh against every
// keyframe (a copy of the algorithm's own mesh) slot by slot and by hash, the final one
// included.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::replay {

struct VerifyReport {
  bool ok = true;
  std::string problem;  // the first problem found, when !ok
  std::uint64_t events = 0, steps = 0;
  std::uint64_t keyframes_checked = 0;  // keyframe visits: slot-by-slot and hash comparisons
};

// progress(pass, fraction) is called now and then (pass 0, 1, 2). Never throws for a bad
// log: an inconsistency is reported in the VerifyReport.
VerifyReport verify(const LogReader& log,
                    const std::function<void(int, double)>& progress = nullptr);

}  // namespace meshstep::replay
