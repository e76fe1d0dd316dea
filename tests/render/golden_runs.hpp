// The recorded runs the golden-image tests draw: refinements of the project's teaching
// example (assets/examples/lesson.poly) by the meshstep program itself, one per algorithm
// whose overlays the tests need, recorded once per test process into a temporary folder.
#pragma once

#include <string>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::golden {

// The log of `meshstep refine lesson.poly ARGUMENTS --record LOG` (recorded on first use).
// Fails the test (and returns nullptr) when the run fails.
const replay::LogReader* lesson_run(const std::string& arguments);

// The log of `meshstep terrain GRID ARGUMENTS --record LOG` on a grid of smooth hills and a
// crater (33 x 25 samples, 10 m apart) that the tests write (recorded on first use).
const replay::LogReader* terrain_run(const std::string& arguments);

std::string asset(const std::string& name);

}  // namespace meshstep::golden
