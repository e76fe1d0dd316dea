// Which moments of a run an export draws: one frame per event, per step, per N steps or
// per phase, between two bounds. A moment is a replay position (events applied).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::app {

struct MomentSpec {
  enum class Unit { event, step, phase } unit = Unit::step;
  std::uint64_t stride = 1;  // every `stride` units
  std::int64_t from = 0;     // first unit (step or event moment; phase: ordinal), inclusive
  std::int64_t to = -1;      // last unit, inclusive; -1: the last there is
};

// Parses --every (event, step, phase or a number N: every N steps). Throws UsageError.
MomentSpec parse_every(const std::string& every, std::int64_t from, std::int64_t to);

// The positions to draw, in order. Step K's frame is the mesh after K steps, as `render
// --step K` draws it (0: before the first step; a run of n steps has n + 1 of them); event
// K's frame is the mesh after K events; a phase's frame is the moment it ends. Throws
// UsageError when the bounds are outside the run.
std::vector<std::uint64_t> frame_moments(const replay::LogReader& log, const MomentSpec& spec);

// Exactly `count` frames spread evenly over `moments` (repeating or skipping moments), for
// a video of a given duration.
std::vector<std::uint64_t> resample(const std::vector<std::uint64_t>& moments, std::size_t count);

}  // namespace meshstep::app
