// A recipe's operations in its log: which steps each one holds. The header names the
// operations (RunHeader::operations); each recorded its phases after the one before, as
// many as recorded_phases() says (run_spec.hpp), so the log's refinement and improvement
// phases, taken in order, fall to the operations without a marker of their own.
#pragma once

#include <cstdint>
#include <vector>

#include "meshstep/refine/run_spec.hpp"
#include "meshstep/replay/log_reader.hpp"

namespace meshstep::replay {

struct OperationSpan {
  Operation operation;
  // The moments before and after it, as step numbers (render --step, log mesh --step):
  // from_step steps were done when it began, to_step when it ended.
  std::uint64_t from_step = 0, to_step = 0;
  bool complete = true;  // false: the log ends before the operation's last phase did
};

// The operations of a recipe's log, in order; empty for a run of one operation. Throws
// InputError (naming the log) when the log has more refinement phases than its operations
// record: a log whose header does not describe its events.
std::vector<OperationSpan> operation_spans(const LogReader& log, const std::string& path);

// The recipe's operation that recorded a refinement or improvement phase of the log (one of
// log.phases()); null for a run of one operation, and for the triangulation's phases.
const Operation* operation_of(const LogReader& log, const PhaseSpan& span);

}  // namespace meshstep::replay
