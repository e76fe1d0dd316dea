// The recorded runs the golden-image and viewer tests draw: refinements of the project's
// teaching example (assets/examples/lesson.poly) by the meshstep program itself, one per
// algorithm whose overlays the tests need, and terrain runs on a grid written here; each
// recorded once per test process into a temporary folder.
#pragma once

#include <string>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::golden {

// The log of `meshstep refine lesson.poly ARGUMENTS --record LOG` (recorded on first use).
// Fails the test (and returns nullptr) when the run fails.
const replay::LogReader* lesson_run(const std::string& arguments);

// The log of `meshstep terrain hills.asc ARGUMENTS --record LOG` on a grid the tests write
// (48 x 36 samples 10 m apart: a peak, a slope and a ripple), recorded on first use. Small
// enough to replay at every step, rich enough that a run has every kind of step: both of
// Lepp-surface's sample choices, the improvement's removals and, with --flips, 3D flips.
const replay::LogReader* terrain_run(const std::string& arguments);

std::string asset(const std::string& name);

}  // namespace meshstep::golden
