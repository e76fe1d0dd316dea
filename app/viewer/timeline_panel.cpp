// The viewer's timeline panel: the transport buttons, the choice of marks, and the bar
// (timeline.hpp draws it).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "panel_style.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

namespace {

// Which kinds the bar marks: a checkbox each, with its colour and how many the run has.
void draw_marks_choice(MarkSet& shown, const TimelineCache& cache) {
  if (ImGui::Button("marks")) ImGui::OpenPopup("timeline marks");
  if (!ImGui::BeginPopup("timeline marks")) return;
  ImGui::TextDisabled("marked along the bar's bottom, a row each");
  for (std::size_t m = 0; m < kMarkCount; ++m) {
    const auto mark = static_cast<Mark>(m);
    ImGui::PushID(static_cast<int>(m));
    ImGui::ColorButton("##colour", ImGui::ColorConvertU32ToFloat4(mark_color(mark)),
                       ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop, ImVec2(12, 12));
    ImGui::SameLine();
    bool on = shown.has(mark);
    char text[96];
    if (cache.counted(mark))
      std::snprintf(text, sizeof text, "%s (%llu)", label(mark), static_cast<unsigned long long>(cache.total_marks[m]));
    else if (cache.scanning() && !marks_steps(mark))
      std::snprintf(text, sizeof text, "%s (counting...)", label(mark));
    else
      std::snprintf(text, sizeof text, "%s", label(mark));
    if (ImGui::Checkbox(text, &on)) shown.set(mark, on);
    ImGui::PopID();
  }
  ImGui::EndPopup();
}

}  // namespace

void Viewer::draw_transport() {
  Session& s = *session_;
  const CursorInfo c = s.cursor_info();
  // Widths grow with the UI scale, as the text in them does; an item that would be cut at
  // the panel's edge (a large scale, a narrow window) goes to the next row instead.
  const float k = ui_scale;
  const auto next_to_last = [](float width) {
    const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
    if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
  };
  if (ImGui::Button("|<")) s.to_start();
  ImGui::SameLine();
  if (ImGui::Button("<<")) s.move(Unit::phase, -1);
  ImGui::SameLine();
  if (ImGui::Button("<")) s.move(Unit::step, -1);
  ImGui::SameLine();
  if (ImGui::Button(s.playback().playing ? "pause" : "play", ImVec2(56 * k, 0))) s.toggle_play();
  ImGui::SameLine();
  if (ImGui::Button(">")) s.move(Unit::step, +1);
  ImGui::SameLine();
  if (ImGui::Button(">>")) s.move(Unit::phase, +1);
  ImGui::SameLine();
  if (ImGui::Button(">|")) s.to_end();
  // Narrow enough for the row to hold the marks button in a 1024-pixel window.
  next_to_last(112 * k);
  ImGui::SetNextItemWidth(112 * k);
  float speed = static_cast<float>(s.playback().speed);
  if (ImGui::SliderFloat("##speed", &speed, static_cast<float>(Playback::kMinSpeed),
                         static_cast<float>(Playback::kMaxSpeed), "%.2f /s", ImGuiSliderFlags_Logarithmic))
    s.playback().speed = speed;
  next_to_last(84 * k);
  ImGui::SetNextItemWidth(84 * k);
  int unit = static_cast<int>(s.playback().unit);
  static const char* const kUnits[] = {"events", "steps", "phases"};
  if (ImGui::Combo("##unit", &unit, kUnits, 3)) s.playback().unit = static_cast<Unit>(unit);
  next_to_last(80 * k);
  ImGui::SetNextItemWidth(80 * k);
  if (ImGui::InputTextWithHint("##goto", "go to step", goto_text_, sizeof goto_text_,
                               ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CharsDecimal)) {
    // A number past the run stays in the box, with the refusal every command gives.
    goto_refusal_ = s.go_to_step(std::strtoll(goto_text_, nullptr, 10));
    if (goto_refusal_.empty()) goto_text_[0] = '\0';
  }
  if (!goto_refusal_.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", goto_refusal_.c_str());
  next_to_last(ImGui::CalcTextSize("marks").x + 2 * ImGui::GetStyle().FramePadding.x);
  draw_marks_choice(timeline_marks, timeline_cache_);
  (void)c;  // the bar itself says where the cursor is (timeline.cpp)
}

void Viewer::draw_timeline(float x, float y, float w, float h) {
  place(x, y, w, h);
  ImGui::Begin("timeline", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  draw_transport();
  draw_timeline_bar(ImGui::GetContentRegionAvail().y - 4.0f);
  ImGui::End();
}

void Viewer::draw_timeline_bar(float height) {
  const replay::LogReader& log = *session_->log();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  if (width < 8.0f || height < 8.0f) return;
  ImGui::InvisibleButton("##timeline", ImVec2(width, height));
  const std::uint64_t events = std::max<std::uint64_t>(1, log.event_count());
  if (ImGui::IsItemActive()) {
    const double t = std::clamp((ImGui::GetIO().MousePos.x - origin.x) / width, 0.0f, 1.0f);
    session_->seek(static_cast<std::uint64_t>(std::llround(t * static_cast<double>(events))));
  }
  draw_timeline_picture(*ImGui::GetWindowDrawList(), log, timeline_cache_, *session_, origin, ImVec2(width, height),
                        timeline_marks, &tick_strip_);
  // The selection's history (a vertex's, a triangle's, a segment's) as ticks along the bar's
  // bottom.
  if (selected_.kind != Picked::Kind::none) {
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    const float bottom = origin.y + height;
    // A click within a few pixels of a tick goes to the end of its step, as its button does
    // (the bar itself would land on the pixel's event).
    const ImGuiIO& io = ImGui::GetIO();
    const bool clicked = ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 9.0f &&
                         io.MousePos.y >= origin.y && io.MousePos.y <= bottom && io.MousePos.x >= origin.x &&
                         io.MousePos.x <= origin.x + width;
    std::uint64_t nearest = kNoEvent;
    float nearest_px = 4.0f;
    for (const std::uint64_t e : selection_story().events) {
      const float x = origin.x + static_cast<float>(static_cast<double>(e) / static_cast<double>(events)) * width;
      draw.AddLine(ImVec2(x, bottom - 16.0f), ImVec2(x, bottom), IM_COL32(204, 121, 167, 255), 2.0f);
      if (clicked && std::abs(io.MousePos.x - x) <= nearest_px) nearest = e, nearest_px = std::abs(io.MousePos.x - x);
    }
    if (nearest != kNoEvent && log.step_of_event(nearest) < log.step_count())
      session_->seek_step(log.step_of_event(nearest) + 1);
  }
}

void Viewer::settle_timeline_marks() {
  if (!timeline_cache_.scan || !timeline_cache_.log) return;  // none, or counted already
  timeline_cache_.wait_for_scan();
  timeline_cache_.update(*timeline_cache_.log, timeline_cache_.columns, timeline_marks);
}

}  // namespace meshstep::viewer
