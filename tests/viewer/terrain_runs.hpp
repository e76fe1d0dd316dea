// The recorded terrain runs the viewer's tests look at: `meshstep terrain` on a small grid
// of hills written here (48 x 36 samples, a peak, a slope and a ripple), recorded once per
// test process into a temporary folder. Small enough to replay at every step, rich enough
// that a run has every kind of step: both of Lepp-surface's sample choices, the
// improvement's removals and, with --flips, the 3D flips.
#pragma once

#include <string>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer::testing {

// The log of `meshstep terrain hills.asc ARGUMENTS --record LOG` (recorded on first use).
// Fails the test (and returns nullptr) when the run fails.
const replay::LogReader* terrain_run(const std::string& arguments);

}  // namespace meshstep::viewer::testing
