// One numbering of a run's steps (step_numbers.hpp).
#include "meshstep/replay/step_numbers.hpp"

#include <algorithm>

namespace meshstep::replay {

std::string step_refusal(const LogReader& log, const std::string& option, std::int64_t k, bool end_allowed) {
  const std::uint64_t n = log.step_count();
  if ((k >= 0 && static_cast<std::uint64_t>(k) <= n) || (end_allowed && k == -1)) return "";
  return log.path() + ": " + option + " " + std::to_string(k) + " is outside the run: its steps are numbered 0.." +
         std::to_string(n) + " (0: before the first step, " + std::to_string(n) + ": after the last" +
         (end_allowed ? std::string("; -1: the end") : std::string()) + ")";
}

std::uint64_t step_position(const LogReader& log, std::uint64_t k) {
  return log.step_start(std::min(k, log.step_count()));
}

StepAt step_at(const LogReader& log, std::uint64_t position) {
  const std::uint64_t done = log.completed_steps_at(position);
  // Inside a step: past its step_begin, before the next one's (or the log's end).
  const bool within = done < log.step_count() && position > log.step_start(done);
  return {within ? done + 1 : done, within};
}

std::uint64_t step_of_event_numbered(const LogReader& log, std::uint64_t e) {
  const std::uint64_t s = log.step_of_event(e);
  return s < log.step_count() ? s + 1 : 0;
}

}  // namespace meshstep::replay
