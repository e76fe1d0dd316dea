// The scene of a recorded run after K steps, with the default options: what the scene
// tests look at.
#pragma once

#include <cstdint>

#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/build.hpp"

namespace meshstep::testing {

inline scene::Scene scene_at_step(const replay::LogReader& log, std::uint64_t step) {
  replay::Replay cursor(log);
  cursor.seek_event(replay::step_position(log, step));
  return build_scene(cursor, scene::SceneOptions{});
}

}  // namespace meshstep::testing
