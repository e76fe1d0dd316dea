// Runs side by side (`meshstep view A.mslog B.mslog ...`): where each run stands when one
// timeline drives them all. No GL and no ImGui: the viewer asks, the tests check.
//
// One run leads (the one with the most steps, so that the timeline spans every run); the
// others follow it, each to the moment that matches the leader's in the chosen sense:
//  - step: after as many steps as the leader has completed;
//  - vertices: the first step boundary at which the follower has inserted at least as many
//    vertices as the leader has at its position (a run that never does rests at its end);
//  - fraction: after the same fraction of its steps as the leader (rounded to the nearest).
// A follower always stands at a step boundary, never inside a step, and a run shorter than
// the leader rests at its end.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer {

enum class SyncMode { step, vertices, fraction };
inline constexpr int kSyncModeCount = 3;
const char* name(SyncMode mode);
std::optional<SyncMode> parse_sync_mode(std::string_view text);

// The vertices the run has inserted after `position` events (input and Steiner alike; a
// vertex removed again still counts: it was inserted).
std::uint64_t inserted_vertices(const replay::LogReader& log, std::uint64_t position);

// The events that inserted the run's vertices, in order: the n-th vertex inserted came with
// [n - 1]. Made once per log (a follower's lookups are then a binary search).
std::vector<std::uint64_t> insertion_events(const replay::LogReader& log);

// The same count from the run's insertion_events: a binary search (every frame, per run).
std::uint64_t inserted_vertices(const std::vector<std::uint64_t>& insertions, std::uint64_t position);

// The follower's position for the leader's.
// `leader_insertions`, `follower_insertions`: insertion_events of each (used only by
// SyncMode::vertices).
std::uint64_t synced_position(const replay::LogReader& leader, const std::vector<std::uint64_t>& leader_insertions,
                              std::uint64_t leader_position, const replay::LogReader& follower,
                              const std::vector<std::uint64_t>& follower_insertions, SyncMode mode);

// The run's steps per phase, in the order the phases first begin (a phase that comes back
// adds to its first entry); a step belongs to the innermost phase its first event is in.
std::vector<std::pair<std::string, std::uint64_t>> steps_per_phase(const replay::LogReader& log);

// Which run leads: the one with the most steps (the first of equals).
std::size_t leading_run(const std::vector<const replay::LogReader*>& logs);

}  // namespace meshstep::viewer
