#include "compare_sync.hpp"

#include <algorithm>
#include <cmath>

namespace meshstep::viewer {

const char* name(SyncMode mode) {
  switch (mode) {
    case SyncMode::step: return "step";
    case SyncMode::vertices: return "vertices";
    case SyncMode::fraction: return "fraction";
  }
  return "?";
}

std::optional<SyncMode> parse_sync_mode(std::string_view text) {
  for (int i = 0; i < kSyncModeCount; ++i)
    if (text == name(static_cast<SyncMode>(i))) return static_cast<SyncMode>(i);
  return std::nullopt;
}

std::vector<std::uint64_t> insertion_events(const replay::LogReader& log) {
  std::vector<std::uint64_t> events;
  events.reserve(log.vertices().size());
  for (const replay::VertexInfo& v : log.vertices())
    if (v.event != kNone) events.push_back(v.event);
  // Vertex ids follow the insertions in most runs, but nothing promises it: sorted here.
  std::sort(events.begin(), events.end());
  return events;
}

std::uint64_t inserted_vertices(const replay::LogReader& log, std::uint64_t position) {
  std::uint64_t n = 0;
  for (const replay::VertexInfo& v : log.vertices())
    if (v.event != kNone && v.event < position) ++n;  // event e is applied after e + 1 events
  return n;
}

std::uint64_t inserted_vertices(const std::vector<std::uint64_t>& insertions, std::uint64_t position) {
  return static_cast<std::uint64_t>(std::lower_bound(insertions.begin(), insertions.end(), position) - insertions.begin());
}

std::uint64_t synced_position(const replay::LogReader& leader, const std::vector<std::uint64_t>& leader_insertions,
                              std::uint64_t leader_position, const replay::LogReader& follower,
                              const std::vector<std::uint64_t>& follower_insertions, SyncMode mode) {
  const std::uint64_t steps = follower.step_count();
  switch (mode) {
    case SyncMode::step:
      return follower.step_start(std::min(leader.completed_steps_at(leader_position), steps));
    case SyncMode::fraction: {
      const std::uint64_t lead_steps = leader.step_count();
      if (lead_steps == 0) return follower.step_start(0);
      const double f = static_cast<double>(leader.completed_steps_at(leader_position)) / static_cast<double>(lead_steps);
      const auto k = static_cast<std::uint64_t>(std::llround(f * static_cast<double>(steps)));
      return follower.step_start(std::min(k, steps));
    }
    case SyncMode::vertices: {
      const std::uint64_t n = inserted_vertices(leader_insertions, leader_position);
      if (n == 0) return follower.step_start(0);
      if (n > follower_insertions.size()) return follower.event_count();  // it never gets there
      // The n-th insertion's step, and the boundary just after it.
      const std::uint64_t e = follower_insertions[n - 1];
      const std::uint64_t k = follower.step_of_event(e);
      if (k >= steps) return follower.step_start(0);  // an event before the first step
      return follower.step_start(k + 1);
    }
  }
  return 0;
}

std::vector<std::pair<std::string, std::uint64_t>> steps_per_phase(const replay::LogReader& log) {
  std::vector<std::pair<std::string, std::uint64_t>> out;
  const std::vector<replay::PhaseSpan>& phases = log.phases();
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    const std::uint64_t at = log.step_start(k);
    // Phases nest: the last one begun at or before the step's first event that has not
    // ended is the innermost.
    const replay::PhaseSpan* inner = nullptr;
    for (const replay::PhaseSpan& p : phases)
      if (p.begin <= at && at < p.end) inner = &p;
    const std::string phase = inner ? replay::name(inner->phase) : "outside any phase";
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == phase; });
    if (it == out.end()) out.emplace_back(phase, 1);
    else ++it->second;
  }
  return out;
}

std::size_t leading_run(const std::vector<const replay::LogReader*>& logs) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < logs.size(); ++i)
    if (logs[i]->step_count() > logs[best]->step_count()) best = i;
  return best;
}

}  // namespace meshstep::viewer
