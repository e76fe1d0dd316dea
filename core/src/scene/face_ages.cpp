// Face ages: which step made the face each slot holds. Forward moves read the writes of
// the events passed; the ages before a write are not kept, so a backward move (or another
// log) counts again from the start.
#include <algorithm>

#include "meshstep/scene/build.hpp"

namespace meshstep::scene {

namespace {

// Did the write make a new triangle (not just mark an edge of the same one constrained)?
bool makes_triangle(const replay::SlotWrite& w) {
  if (w.after.dead()) return false;
  if (w.before.dead()) return true;
  for (const VertexId v : w.after.v)
    if (std::find(w.before.v.begin(), w.before.v.end(), v) == w.before.v.end()) return true;
  return false;
}

}  // namespace

void FaceAges::update(const replay::Replay& cursor) {
  const replay::LogReader& log = cursor.log();
  const std::uint64_t target = cursor.position();
  if (log_ != &log || target < position_) {
    age_.clear();
    position_ = 0;
    log_ = &log;
  }
  if (target == position_) return;
  // Step by step, so that each event's step is known without a search; events of the
  // preamble (before the first step) count as step 0.
  std::uint64_t step = position_ < log.step_start(0) ? 0 : log.step_of_event(position_);
  if (step == log.step_count()) step = 0;
  for (std::uint64_t e = position_; e < target; ++e) {
    while (step + 1 < log.step_count() && log.step_start(step + 1) <= e) ++step;
    for (const replay::SlotWrite& w : log.writes(e)) {
      if (!makes_triangle(w)) continue;
      if (w.slot >= age_.size()) age_.resize(std::max<std::size_t>(w.slot + 1, age_.size() * 3 / 2), 0);
      age_[w.slot] = step;
    }
  }
  position_ = target;
}

}  // namespace meshstep::scene
