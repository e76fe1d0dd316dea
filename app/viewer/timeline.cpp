#include "timeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "session.hpp"

namespace meshstep::viewer {

namespace {

// Okabe-Ito colours, one per phase (insert vertices, recover segments, carve, refine,
// improve), light enough for black text.
constexpr ImU32 kPhaseColors[] = {IM_COL32(86, 180, 233, 150), IM_COL32(230, 159, 0, 150),
                                  IM_COL32(204, 121, 167, 150), IM_COL32(0, 158, 115, 150),
                                  IM_COL32(240, 228, 66, 150)};

}  // namespace

int column_of(std::uint64_t position, std::uint64_t event_count, int columns) {
  if (columns <= 1 || event_count == 0) return 0;
  const auto c = static_cast<int>(static_cast<double>(position) / static_cast<double>(event_count) * columns);
  return std::clamp(c, 0, columns - 1);
}

void TimelineCache::wait_for_scan() const {
  while (scanning()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

void TimelineCache::update(const replay::LogReader& reader, int width, MarkSet wanted) {
  const bool new_log = log != &reader;
  if (new_log) {
    events_scanned = false;
    for (std::vector<std::uint64_t>& p : event_positions) std::vector<std::uint64_t>().swap(p);
    scan.reset();
  }
  if (wanted.any_event_kind() && !events_scanned && !scan) {
    scan = std::make_unique<EventMarkScan>();
    scan->start(reader.path());
  }
  const bool arrived = scan && scan->ready();
  if (arrived) {
    event_positions = scan->take();
    events_scanned = true;
    scan.reset();
  }
  if (!new_log && columns == width && !arrived) return;
  log = &reader;
  columns = width;
  static std::uint64_t stamps = 0;  // the UI thread's
  stamp = ++stamps;

  const auto w = static_cast<std::size_t>(std::max(0, width));
  steps.assign(w, 0);
  for (std::size_t m = 0; m < kMarkCount; ++m) {
    const bool countable = marks_steps(static_cast<Mark>(m)) || events_scanned;
    if (countable) marks[m].assign(w, 0);
    else marks[m].clear();
  }
  const std::uint64_t events = reader.event_count();
  if (w > 0) {
    for (std::uint64_t k = 0; k < reader.step_count(); ++k) {
      const auto c = static_cast<std::size_t>(column_of(reader.step_start(k + 1), events, width));
      ++steps[c];
      for (std::size_t m = 0; m < kMarkCount; ++m)
        if (marks_steps(static_cast<Mark>(m))) marks[m][c] += marks_step(static_cast<Mark>(m), reader.step_kind(k));
    }
    if (events_scanned)
      for (std::size_t m = 0; m < kMarkCount; ++m)
        for (const std::uint64_t position : event_positions[m])
          ++marks[m][static_cast<std::size_t>(column_of(position, events, width))];
  }
  most_steps = steps.empty() ? 0 : *std::max_element(steps.begin(), steps.end());
  for (std::size_t m = 0; m < kMarkCount; ++m) {
    most_marks[m] = marks[m].empty() ? 0 : *std::max_element(marks[m].begin(), marks[m].end());
    total_marks[m] = 0;
    for (const std::uint32_t n : marks[m]) total_marks[m] += n;
  }
}

ImU32 mark_color(Mark mark) {
  // Okabe-Ito: the splits keep the vermillion they always had; reddish purple is left to
  // the selected vertex's history.
  static constexpr ImU32 kColors[kMarkCount] = {
      IM_COL32(213, 94, 0, 255),    // splits: vermillion
      IM_COL32(240, 228, 66, 255),  // rejected points: yellow
      IM_COL32(86, 180, 233, 255),  // cavities: sky blue
      IM_COL32(0, 114, 178, 255),   // flips: blue
      IM_COL32(0, 158, 115, 255),   // refinement steps: bluish green
      IM_COL32(230, 159, 0, 255),   // triangulation steps: orange
  };
  return kColors[static_cast<std::size_t>(mark)];
}

void tick_strip_pixels(const TimelineCache& cache, scene::Image& image) {
  // Each column's tick as its line drew it in its middle: the light grey at the column's
  // strength over the bar's background.
  constexpr float kBar[3] = {40.0f, 40.0f, 46.0f};
  image.width = std::max(0, cache.columns);
  image.height = 1;
  image.rgba.resize(static_cast<std::size_t>(image.width) * 4);  // no allocation at the same width
  for (int c = 0; c < image.width; ++c) {
    const std::uint32_t n = cache.steps[static_cast<std::size_t>(c)];
    const float strength = n == 0 ? 0.0f : 0.25f + 0.75f * static_cast<float>(n) / static_cast<float>(cache.most_steps);
    const float a = static_cast<float>(static_cast<int>(255 * strength)) / 255.0f;
    std::uint8_t* px = image.rgba.data() + 4 * static_cast<std::size_t>(c);
    for (int k = 0; k < 3; ++k) px[k] = static_cast<std::uint8_t>(std::lround(220.0f * a + kBar[k] * (1.0f - a)));
    px[3] = 255;
  }
}

void draw_timeline_picture(ImDrawList& draw, const replay::LogReader& log, TimelineCache& cache, const Session& session,
                           ImVec2 origin, ImVec2 size, MarkSet shown, TickStrip* strip) {
  const int width = static_cast<int>(size.x);
  cache.update(log, width, shown);
  const std::uint64_t events = std::max<std::uint64_t>(1, log.event_count());
  const auto x_of = [&](std::uint64_t position) {
    return origin.x + static_cast<float>(static_cast<double>(position) / static_cast<double>(events)) * size.x;
  };
  const float top = origin.y, bottom = origin.y + size.y;
  const float band_bottom = top + 0.45f * size.y;
  draw.AddRectFilled(origin, ImVec2(origin.x + size.x, bottom), IM_COL32(40, 40, 46, 255));

  // Phases, with their names where they fit. In a recipe's log each refinement phase is
  // named after its operation ("2: refine"), and a line marks where each operation begins
  // (its phases follow from the operations alone: replay/operations.hpp).
  const std::vector<Operation>& operations = log.run().operations;
  std::size_t operation = 0, phases_left = operations.empty() ? 0 : recorded_phases(operations[0]);
  for (const replay::PhaseSpan& p : log.phases()) {
    const float x0 = x_of(p.begin), x1 = std::max(x0 + 1.0f, x_of(std::min(p.end, log.event_count())));
    const auto i = static_cast<std::size_t>(p.phase);
    draw.AddRectFilled(ImVec2(x0, top), ImVec2(x1, band_bottom), kPhaseColors[i % 5]);
    static constexpr const char* kLabels[] = {"insert vertices", "recover segments", "carve", "refine", "improve"};
    const char* label = i < 5 ? kLabels[i] : replay::name(p.phase);
    char numbered[48];
    const bool of_an_operation = p.phase == replay::Phase::refine || p.phase == replay::Phase::improve;
    if (of_an_operation && operation < operations.size()) {
      if (phases_left == recorded_phases(operations[operation]))
        draw.AddLine(ImVec2(x0, top), ImVec2(x0, bottom), IM_COL32(255, 255, 255, 200), 2.0f);
      std::snprintf(numbered, sizeof numbered, "%zu: %s", operation + 1, label);
      label = numbered;
      if (--phases_left == 0 && ++operation < operations.size()) phases_left = recorded_phases(operations[operation]);
    }
    const ImVec2 text = ImGui::CalcTextSize(label);
    if (text.x + 8.0f < x1 - x0) draw.AddText(ImVec2(x0 + 4.0f, top + 2.0f), IM_COL32(255, 255, 255, 230), label);
  }

  // The chosen kinds' marks, a row each from the bar's bottom up, in Mark order; the step
  // ticks stand above them. Rows are 8 pixels high, less when many would leave the ticks
  // no room.
  std::size_t rows = 0;
  for (std::size_t m = 0; m < kMarkCount; ++m)
    rows += shown.has(static_cast<Mark>(m)) && cache.counted(static_cast<Mark>(m));
  const float below_bands = bottom - band_bottom - 2.0f;
  const float row_height =
      rows == 0 ? 0.0f : std::clamp((below_bands - 8.0f) / static_cast<float>(rows), 3.0f, 8.0f);
  const float ticks_bottom = bottom - 2.0f - static_cast<float>(rows) * row_height;

  // Steps: one tick each when they have room, else their density per column.
  const bool ticks = log.step_count() > 0 && static_cast<double>(log.step_count()) * 3.0 < size.x;
  if (!ticks && strip && cache.columns > 0 && ticks_bottom > band_bottom + 2.0f) {
    if (strip->stamp != cache.stamp) {
      tick_strip_pixels(cache, strip->image);
      if (!strip->texture) strip->texture = std::make_unique<PictureTexture>();
      strip->texture->upload(strip->image);
      strip->stamp = cache.stamp;
    }
    opaque_image_at(draw, strip->texture->id(), ImVec2(origin.x, band_bottom + 2.0f),
                    ImVec2(origin.x + static_cast<float>(cache.columns), ticks_bottom));
  } else for (int c = 0; c < cache.columns; ++c) {
    const std::uint32_t n = cache.steps[static_cast<std::size_t>(c)];
    if (n == 0) continue;
    const float x = origin.x + static_cast<float>(c) + 0.5f;
    const float strength = ticks ? 1.0f : 0.25f + 0.75f * static_cast<float>(n) / static_cast<float>(cache.most_steps);
    draw.AddLine(ImVec2(x, band_bottom + 2.0f), ImVec2(x, ticks_bottom),
                 IM_COL32(220, 220, 220, static_cast<int>(255 * strength)));
  }
  std::size_t row = 0;
  for (std::size_t m = 0; m < kMarkCount; ++m) {
    const auto mark = static_cast<Mark>(m);
    if (!shown.has(mark) || !cache.counted(mark)) continue;
    const float y1 = bottom - 2.0f - static_cast<float>(row++) * row_height, y0 = y1 - (row_height - 1.0f);
    const ImU32 color = mark_color(mark);
    const std::vector<std::uint32_t>& counts = cache.marks[m];
    for (int c = 0; c < cache.columns; ++c) {
      const std::uint32_t n = counts[static_cast<std::size_t>(c)];
      if (n == 0) continue;
      // A column with more of them is stronger: a density, as the ticks have.
      const float strength = 0.4f + 0.6f * static_cast<float>(n) / static_cast<float>(cache.most_marks[m]);
      const float x = origin.x + static_cast<float>(c) + 0.5f;
      draw.AddRectFilled(ImVec2(x - 1.5f, y0), ImVec2(x + 1.5f, y1),
                         (color & ~IM_COL32_A_MASK) | (static_cast<ImU32>(255 * strength) << IM_COL32_A_SHIFT));
    }
  }

  // Bookmarks and the cursor.
  for (int slot = 1; slot <= 9; ++slot)
    if (const auto at = session.bookmark(slot)) {
      const float x = x_of(*at);
      char label[2] = {static_cast<char>('0' + slot), '\0'};
      draw.AddTriangleFilled(ImVec2(x - 5.0f, top), ImVec2(x + 5.0f, top), ImVec2(x, top + 7.0f),
                             IM_COL32(255, 255, 255, 255));
      draw.AddText(ImVec2(x + 5.0f, top), IM_COL32(255, 255, 255, 255), label);
    }
  const CursorInfo c = session.cursor_info();
  const float cx = x_of(c.position);
  draw.AddLine(ImVec2(cx, top), ImVec2(cx, bottom), IM_COL32(255, 60, 60, 255), 2.0f);

  // Where the cursor is, in numbers, at the bar's right end over the bands.
  // The caption's step number: "step 34/50" at the mesh after 34 steps, "in step 34/50"
  // while its events are being applied (step_numbers.hpp).
  char where[112];
  std::snprintf(where, sizeof where, "%sstep %llu/%llu \u00B7 event %llu/%llu", c.within ? "in " : "",
                static_cast<unsigned long long>(c.step), static_cast<unsigned long long>(c.step_count),
                static_cast<unsigned long long>(c.position), static_cast<unsigned long long>(c.event_count));
  const ImVec2 text = ImGui::CalcTextSize(where);
  const ImVec2 at(origin.x + size.x - text.x - 6.0f, top + 2.0f);
  draw.AddRectFilled(ImVec2(at.x - 4.0f, top), ImVec2(origin.x + size.x, top + text.y + 4.0f), IM_COL32(20, 20, 24, 220));
  draw.AddText(at, IM_COL32(255, 255, 255, 255), where);
}

}  // namespace meshstep::viewer
