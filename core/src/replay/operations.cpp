// operation_spans (replay/operations.hpp).
#include "meshstep/replay/operations.hpp"

#include "meshstep/error.hpp"

namespace meshstep::replay {

namespace {

// Steps begun before the event at `position`: the moment just before it.
std::uint64_t steps_before(const LogReader& log, std::uint64_t position) {
  if (position == 0) return 0;
  const std::uint64_t step = log.step_of_event(position - 1);
  return step == log.step_count() ? 0 : step + 1;
}

}  // namespace

std::vector<OperationSpan> operation_spans(const LogReader& log, const std::string& path) {
  const std::vector<Operation>& operations = log.run().operations;
  std::vector<OperationSpan> spans;
  if (operations.empty()) return spans;
  std::vector<PhaseSpan> phases;  // the refinement's, in order
  for (const PhaseSpan& p : log.phases())
    if (p.phase == Phase::refine || p.phase == Phase::improve) phases.push_back(p);
  std::size_t next = 0;
  for (const Operation& op : operations) {
    OperationSpan span{op};
    const std::size_t count = recorded_phases(op);
    if (next >= phases.size()) {
      // Never begun: the log ends before it (a run that died or was stopped).
      span.from_step = span.to_step = log.step_count();
      span.complete = false;
    } else {
      span.from_step = steps_before(log, phases[next].begin);
      const std::size_t last = std::min(next + count, phases.size()) - 1;
      span.complete = next + count <= phases.size() && phases[last].end != kNoEnd;
      span.to_step = span.complete ? steps_before(log, phases[last].end) : log.step_count();
    }
    next += count;
    spans.push_back(std::move(span));
  }
  if (next < phases.size())
    throw InputError(path, 0,
                     "the log has " + std::to_string(phases.size()) + " refinement phases, more than the " +
                         std::to_string(next) + " its header's operations record");
  return spans;
}

const Operation* operation_of(const LogReader& log, const PhaseSpan& span) {
  const std::vector<Operation>& operations = log.run().operations;
  if (operations.empty() || (span.phase != Phase::refine && span.phase != Phase::improve)) return nullptr;
  std::size_t before = 0;  // the refinement phases before it
  for (const PhaseSpan& p : log.phases()) {
    if (p.begin >= span.begin) break;
    before += p.phase == Phase::refine || p.phase == Phase::improve;
  }
  for (const Operation& op : operations) {
    const std::size_t count = recorded_phases(op);
    if (before < count) return &op;
    before -= count;
  }
  return nullptr;
}

}  // namespace meshstep::replay
