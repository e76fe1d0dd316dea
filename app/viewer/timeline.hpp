// The timeline: one bar over the whole run. Phases are coloured bands, steps are ticks (or,
// when there are more steps than pixels, a density: how many steps each column holds), the
// kinds of step and event a person chose are marked (timeline_marks.hpp: segment splits
// unless chosen otherwise), each kind in a row of its own colour along the bar's bottom,
// and the cursor and the bookmarks stand over it.
#pragma once

#include <array>
#include <memory>
#include <cstdint>
#include <vector>

#include <imgui.h>

#include "picture_texture.hpp"

#include "meshstep/replay/log_reader.hpp"
#include "event_mark_scan.hpp"
#include "timeline_marks.hpp"

namespace meshstep::viewer {

class Session;

// The columns of the bar, counted once per log and width (a million steps take a few
// milliseconds to count; a frame then only draws). The kinds that mark events need one pass
// over the log's events: it is made the first time one of them is wanted (not when the log
// opens, so that a person who never asks for them never waits for it), on a thread of its
// own (event_mark_scan.hpp), and its positions of all of them are kept so that a new width
// is counted without reading the log again. Until the pass ends those kinds are uncounted.
struct TimelineCache {
  const replay::LogReader* log = nullptr;
  int columns = 0;
  std::vector<std::uint32_t> steps;  // step ends per column
  std::uint32_t most_steps = 0;
  // Per kind: its marks per column (empty until counted), the most in one column, and all.
  std::array<std::vector<std::uint32_t>, kMarkCount> marks;
  std::array<std::uint32_t, kMarkCount> most_marks{};
  std::array<std::uint64_t, kMarkCount> total_marks{};
  // The event kinds' positions (just after each event), once the pass has been made.
  bool events_scanned = false;
  std::array<std::vector<std::uint64_t>, kMarkCount> event_positions;
  std::unique_ptr<EventMarkScan> scan;  // the pass, while it runs
  std::uint64_t stamp = 0;  // new (in the whole program) whenever the counts are made anew

  // Counts again when the log or the width changed, or when `wanted` asks for event kinds
  // whose pass has not been made yet.
  void update(const replay::LogReader& log, int columns, MarkSet wanted);
  // Whether kind `m` has been counted (an event kind: once its pass was made).
  bool counted(Mark m) const { return !marks[static_cast<std::size_t>(m)].empty(); }
  // Whether the pass over the events runs (scripts wait for it before they look).
  bool scanning() const { return scan && !scan->ready(); }
  // Blocks until the pass (if one runs) has ended; the next update() counts it.
  void wait_for_scan() const;
};

// The bar's column of an event position (0 .. columns - 1).
int column_of(std::uint64_t position, std::uint64_t event_count, int columns);

// The colour of a kind's marks (Okabe-Ito, as the phases are).
ImU32 mark_color(Mark mark);

// The step ticks of a long run (a density per column, every column drawn) as one texture
// of a pixel per column, drawn as one quad. As a thin antialiased line per column they
// took llvmpipe about 3.5 ms of an idle frame's 18 ms of CPU with four runs side by side;
// as a strip, 1.5 ms less (docs/viewer.md). Made again when the counts change; a run of
// few steps keeps its ticks as lines.
struct TickStrip {
  std::unique_ptr<PictureTexture> texture;  // made on the UI thread when first wanted
  scene::Image image;                       // columns x 1, opaque: the ticks over the bar
  std::uint64_t stamp = 0;                  // the counts it shows (TimelineCache::stamp)
};

// The strip's pixels for the cache's step counts: a column without a step is the bar's
// background, the others light grey at the strength the lines had (0.25 + 0.75 of their
// share of the fullest column), over it.
void tick_strip_pixels(const TimelineCache& cache, scene::Image& image);

// `strip`: where the ticks of a long run are drawn from (none: as lines).
void draw_timeline_picture(ImDrawList& draw, const replay::LogReader& log, TimelineCache& cache, const Session& session,
                           ImVec2 origin, ImVec2 size, MarkSet shown, TickStrip* strip = nullptr);

}  // namespace meshstep::viewer
