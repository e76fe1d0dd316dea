// The viewer's timeline panel: the transport buttons and the bar (timeline.hpp draws it).
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "panel_style.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

void Viewer::draw_transport() {
  Session& s = *session_;
  const CursorInfo c = s.cursor_info();
  if (ImGui::Button("|<")) s.to_start();
  ImGui::SameLine();
  if (ImGui::Button("<<")) s.move(Unit::phase, -1);
  ImGui::SameLine();
  if (ImGui::Button("<")) s.move(Unit::step, -1);
  ImGui::SameLine();
  if (ImGui::Button(s.playback().playing ? "pause" : "play", ImVec2(56, 0))) s.toggle_play();
  ImGui::SameLine();
  if (ImGui::Button(">")) s.move(Unit::step, +1);
  ImGui::SameLine();
  if (ImGui::Button(">>")) s.move(Unit::phase, +1);
  ImGui::SameLine();
  if (ImGui::Button(">|")) s.to_end();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(150);
  float speed = static_cast<float>(s.playback().speed);
  if (ImGui::SliderFloat("##speed", &speed, static_cast<float>(Playback::kMinSpeed),
                         static_cast<float>(Playback::kMaxSpeed), "%.2f /s", ImGuiSliderFlags_Logarithmic))
    s.playback().speed = speed;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  int unit = static_cast<int>(s.playback().unit);
  static const char* const kUnits[] = {"events", "steps", "phases"};
  if (ImGui::Combo("##unit", &unit, kUnits, 3)) s.playback().unit = static_cast<Unit>(unit);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  if (ImGui::InputTextWithHint("##goto", "go to step", goto_text_, sizeof goto_text_,
                               ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CharsDecimal)) {
    s.seek_step(std::strtoull(goto_text_, nullptr, 10));
    goto_text_[0] = '\0';
  }
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
  draw_timeline_picture(*ImGui::GetWindowDrawList(), log, timeline_cache_, *session_, origin, ImVec2(width, height));
  // The selected vertex's history as ticks along the bar's bottom.
  if (selected_.kind == Picked::Kind::vertex) {
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    const float bottom = origin.y + height;
    for (const std::uint32_t e : history_.events_of_vertex(selected_.index)) {
      const float x = origin.x + static_cast<float>(static_cast<double>(e) / static_cast<double>(events)) * width;
      draw.AddLine(ImVec2(x, bottom - 16.0f), ImVec2(x, bottom), IM_COL32(204, 121, 167, 255), 2.0f);
    }
  }
}

}  // namespace meshstep::viewer
