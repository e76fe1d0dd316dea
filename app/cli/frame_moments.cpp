#include "frame_moments.hpp"

#include <charconv>

#include "draw_options.hpp"
#include "meshstep/replay/step_numbers.hpp"

namespace meshstep::app {

MomentSpec parse_every(const std::string& every, std::int64_t from, std::int64_t to) {
  MomentSpec spec;
  spec.from = from;
  spec.to = to;
  if (every == "event") spec.unit = MomentSpec::Unit::event;
  else if (every == "step") spec.unit = MomentSpec::Unit::step;
  else if (every == "phase") spec.unit = MomentSpec::Unit::phase;
  else {
    std::uint64_t n = 0;
    const auto [ptr, ec] = std::from_chars(every.data(), every.data() + every.size(), n);
    if (ec != std::errc() || ptr != every.data() + every.size() || n == 0)
      throw UsageError("--every " + every + ": expected event, step, phase or a number of steps N >= 1");
    spec.unit = MomentSpec::Unit::step;
    spec.stride = n;
  }
  if (from < 0) throw UsageError("--from " + std::to_string(from) + ": expected a number >= 0");
  if (to < -1) throw UsageError("--to " + std::to_string(to) + ": expected a number >= 0 (or -1: the end)");
  return spec;
}

std::vector<std::uint64_t> frame_moments(const replay::LogReader& log, const MomentSpec& spec) {
  using Unit = MomentSpec::Unit;
  // The position each numbered unit names. Steps and events are moments, as `render --step`
  // and `render --event` number them: step K is the mesh after K steps (0..n, in the words
  // of step_numbers.hpp), event K the mesh after K events (0..E). A phase's frame is the
  // moment it ends.
  std::vector<std::uint64_t> ends;
  const char* unit_name = "step";
  if (spec.unit == Unit::event) {
    unit_name = "event";
    ends.resize(log.event_count() + 1);
    for (std::uint64_t e = 0; e < ends.size(); ++e) ends[e] = e;
  } else if (spec.unit == Unit::step) {
    for (std::uint64_t k = 0; k <= log.step_count(); ++k) ends.push_back(replay::step_position(log, k));
  } else {
    unit_name = "phase";
    for (std::uint64_t e = 0; e < log.event_count(); ++e)
      if (log.event(e).type == replay::EventType::phase_end) ends.push_back(e + 1);
  }
  if (ends.empty() || (spec.unit == Unit::step && log.step_count() == 0))
    throw UsageError(log.path() + ": the run has no " + std::string(unit_name) + " to draw");
  const std::uint64_t last = ends.size() - 1;
  if (spec.unit == Unit::step) {
    // The words every command refuses a step number in.
    std::string refused = replay::step_refusal(log, "--from", spec.from, false);
    if (refused.empty()) refused = replay::step_refusal(log, "--to", spec.to);
    if (!refused.empty()) throw UsageError(refused);
  }
  const std::uint64_t from = static_cast<std::uint64_t>(spec.from);
  const std::uint64_t to = spec.to < 0 ? last : static_cast<std::uint64_t>(spec.to);
  if (from > last || to > last)
    throw UsageError(log.path() + ": --from " + std::to_string(spec.from) + " --to " + std::to_string(spec.to) +
                     " is outside the run: its " + unit_name + "s are numbered 0.." + std::to_string(last));
  if (from > to)
    throw UsageError(log.path() + ": --from " + std::to_string(spec.from) + " comes after --to " +
                     std::to_string(spec.to) + ": nothing to draw");
  std::vector<std::uint64_t> moments;
  for (std::uint64_t u = from; u <= to; u += spec.stride) moments.push_back(ends[u]);
  // A stride that skips the last unit still ends on it: the animation shows the result.
  if (moments.back() != ends[to]) moments.push_back(ends[to]);
  return moments;
}

std::vector<std::uint64_t> resample(const std::vector<std::uint64_t>& moments, std::size_t count) {
  std::vector<std::uint64_t> out;
  if (moments.empty()) return out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    // Frame i shows moment floor(i * M / count); the last frame the last moment.
    const std::size_t m = count == 1 ? moments.size() - 1 : i * (moments.size() - 1) / (count - 1);
    out.push_back(moments[m]);
  }
  return out;
}

}  // namespace meshstep::app
