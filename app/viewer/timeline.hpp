// The timeline: one bar over the whole run. Phases are coloured bands, steps are ticks (or,
// when there are more steps than pixels, a density: how many steps each column holds),
// segment splits are marked, and the cursor and the bookmarks stand over it.
#pragma once

#include <cstdint>
#include <vector>

#include <imgui.h>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer {

class Session;

// The columns of the bar, counted once per log and width (a million steps take a few
// milliseconds to count; a frame then only draws).
struct TimelineCache {
  const replay::LogReader* log = nullptr;
  int columns = 0;
  std::vector<std::uint32_t> steps, splits;  // step ends per column; segment splits among them
  std::uint32_t most_steps = 0;

  // Counts again when the log or the width changed.
  void update(const replay::LogReader& log, int columns);
};

// The bar's column of an event position (0 .. columns - 1).
int column_of(std::uint64_t position, std::uint64_t event_count, int columns);

void draw_timeline_picture(ImDrawList& draw, const replay::LogReader& log, TimelineCache& cache, const Session& session,
                           ImVec2 origin, ImVec2 size);

}  // namespace meshstep::viewer
