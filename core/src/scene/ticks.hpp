// Round numbers for a legend's ticks, and their labels.
#pragma once

#include <string>
#include <vector>

namespace meshstep::scene::detail {

// Ticks for a linear scale over [lo, hi]: the multiples of a step of 1, 2 or 5 times a power
// of ten that lie in the range, about `target` of them (at least the range's ends when it is
// a single value).
std::vector<double> linear_ticks(double lo, double hi, int target = 6);
// The step between linear ticks (for their labels' decimals).
double tick_step(double lo, double hi, int target = 6);

// Ticks for a log scale over [lo, hi] (both > 0): powers of ten, with 2 and 5 times them when
// the range spans less than two decades; about `target` of them at most.
std::vector<double> log_ticks(double lo, double hi, int target = 7);

// A number as people read it on a scale whose ticks are `step` apart: as many decimals as
// the step needs and no more ("0.25", "40", "1e-05" for the very small or large).
std::string tick_label(double value, double step);
// A tick of a log scale: "0.001", "0.5", "20", "1e+06".
std::string log_tick_label(double value);

}  // namespace meshstep::scene::detail
