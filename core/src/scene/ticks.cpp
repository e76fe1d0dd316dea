#include "ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>

namespace meshstep::scene::detail {

namespace {

// The tick step: the first of 1, 2, 5 x 10^k that gives at most `target` intervals.
double nice_step(double span, int target) {
  const double rough = span / std::max(1, target - 1);
  const double decade = std::pow(10.0, std::floor(std::log10(rough)));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= rough * (1.0 - 1e-9)) return m * decade;
  return 10.0 * decade;
}

std::string printed(const char* format, double value) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

}  // namespace

double tick_step(double lo, double hi, int target) {
  const double span = hi - lo;
  if (!(span > 0.0) || !std::isfinite(span)) return 0.0;
  return nice_step(span, target);
}

std::vector<double> linear_ticks(double lo, double hi, int target) {
  const double step = tick_step(lo, hi, target);
  if (step == 0.0) return {lo};
  std::vector<double> out;
  // Multiples of the step from the first at or above lo; rounding noise (0.1 * 3) is taken
  // out by computing each tick as k * step.
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1.0) {
    const double v = k * step;
    out.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
  }
  return out;
}

std::vector<double> log_ticks(double lo, double hi, int target) {
  if (!(lo > 0.0) || !(hi >= lo)) return {};
  if (hi == lo) return {lo};
  const double first = std::floor(std::log10(lo) + 1e-9), last = std::ceil(std::log10(hi) - 1e-9);
  const double decades = std::log10(hi) - std::log10(lo);
  const double multiples_few[] = {1.0}, multiples_many[] = {1.0, 2.0, 5.0};
  const bool dense = decades < 2.0;
  std::vector<double> out;
  for (double e = first; e <= last; e += 1.0)
    for (const double m : dense ? std::span<const double>(multiples_many) : std::span<const double>(multiples_few)) {
      const double v = m * std::pow(10.0, e);
      if (v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9)) out.push_back(v);
    }
  // Many decades: keep every k-th power so the labels do not collide.
  if (static_cast<int>(out.size()) > target) {
    const std::size_t every = (out.size() + target - 1) / target;
    std::vector<double> thinned;
    for (std::size_t i = 0; i < out.size(); i += every) thinned.push_back(out[i]);
    out = std::move(thinned);
  }
  // A range within one decade may hold fewer than two 1-2-5 values: round linear ticks then
  // (placed on the log scale all the same).
  if (out.size() < 2) out = linear_ticks(lo, hi, 4);
  return out;
}

std::string tick_label(double value, double step) {
  const double magnitude = std::max(std::abs(value), step);
  if (magnitude != 0.0 && (magnitude >= 1e6 || magnitude < 1e-4)) return printed("%.3g", value);
  const int decimals = step > 0.0 && step < 1.0 ? static_cast<int>(std::ceil(-std::log10(step) - 1e-9)) : 0;
  char format[16];
  std::snprintf(format, sizeof format, "%%.%df", std::clamp(decimals, 0, 9));
  return printed(format, value);
}

std::string log_tick_label(double value) {
  if (value >= 1e-4 && value < 1e6) return printed("%.6g", value);
  return printed("%.3g", value);
}

}  // namespace meshstep::scene::detail
