#include "timeline.hpp"

#include <algorithm>
#include <cstdio>

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

void TimelineCache::update(const replay::LogReader& reader, int width) {
  if (log == &reader && columns == width) return;
  log = &reader;
  columns = width;
  steps.assign(static_cast<std::size_t>(width), 0);
  splits.assign(static_cast<std::size_t>(width), 0);
  const std::uint64_t events = reader.event_count();
  for (std::uint64_t k = 0; k < reader.step_count(); ++k) {
    const auto c = static_cast<std::size_t>(column_of(reader.step_start(k + 1), events, width));
    ++steps[c];
    splits[c] += reader.step_kind(k) == replay::StepKind::split_segment;
  }
  most_steps = steps.empty() ? 0 : *std::max_element(steps.begin(), steps.end());
}

void draw_timeline_picture(ImDrawList& draw, const replay::LogReader& log, TimelineCache& cache, const Session& session,
                           ImVec2 origin, ImVec2 size) {
  const int width = static_cast<int>(size.x);
  cache.update(log, width);
  const std::uint64_t events = std::max<std::uint64_t>(1, log.event_count());
  const auto x_of = [&](std::uint64_t position) {
    return origin.x + static_cast<float>(static_cast<double>(position) / static_cast<double>(events)) * size.x;
  };
  const float top = origin.y, bottom = origin.y + size.y;
  const float band_bottom = top + 0.45f * size.y;
  draw.AddRectFilled(origin, ImVec2(origin.x + size.x, bottom), IM_COL32(40, 40, 46, 255));

  // Phases, with their names where they fit.
  for (const replay::PhaseSpan& p : log.phases()) {
    const float x0 = x_of(p.begin), x1 = std::max(x0 + 1.0f, x_of(std::min(p.end, log.event_count())));
    const auto i = static_cast<std::size_t>(p.phase);
    draw.AddRectFilled(ImVec2(x0, top), ImVec2(x1, band_bottom), kPhaseColors[i % 5]);
    static constexpr const char* kLabels[] = {"insert vertices", "recover segments", "carve", "refine", "improve"};
    const char* label = i < 5 ? kLabels[i] : replay::name(p.phase);
    const ImVec2 text = ImGui::CalcTextSize(label);
    if (text.x + 8.0f < x1 - x0) draw.AddText(ImVec2(x0 + 4.0f, top + 2.0f), IM_COL32(255, 255, 255, 230), label);
  }

  // Steps: one tick each when they have room, else their density per column.
  const bool ticks = log.step_count() > 0 && static_cast<double>(log.step_count()) * 3.0 < size.x;
  for (int c = 0; c < cache.columns; ++c) {
    const std::uint32_t n = cache.steps[static_cast<std::size_t>(c)];
    if (n == 0) continue;
    const float x = origin.x + static_cast<float>(c) + 0.5f;
    const float strength = ticks ? 1.0f : 0.25f + 0.75f * static_cast<float>(n) / static_cast<float>(cache.most_steps);
    draw.AddLine(ImVec2(x, band_bottom + 2.0f), ImVec2(x, bottom - 10.0f),
                 IM_COL32(220, 220, 220, static_cast<int>(255 * strength)));
    if (cache.splits[static_cast<std::size_t>(c)])
      draw.AddRectFilled(ImVec2(x - 1.5f, bottom - 9.0f), ImVec2(x + 1.5f, bottom - 2.0f), IM_COL32(213, 94, 0, 255));
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
  char where[96];
  std::snprintf(where, sizeof where, "step %llu/%llu \u00B7 event %llu/%llu", static_cast<unsigned long long>(c.step),
                static_cast<unsigned long long>(c.step_count), static_cast<unsigned long long>(c.position),
                static_cast<unsigned long long>(c.event_count));
  const ImVec2 text = ImGui::CalcTextSize(where);
  const ImVec2 at(origin.x + size.x - text.x - 6.0f, top + 2.0f);
  draw.AddRectFilled(ImVec2(at.x - 4.0f, top), ImVec2(origin.x + size.x, top + text.y + 4.0f), IM_COL32(20, 20, 24, 220));
  draw.AddText(at, IM_COL32(255, 255, 255, 255), where);
}

}  // namespace meshstep::viewer
