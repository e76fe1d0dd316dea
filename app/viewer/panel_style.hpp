// What the viewer's fixed panels share: they neither move, resize, collapse nor keep ImGui
// settings (the viewer lays them out every frame), and are placed before they begin.
#pragma once

#include <imgui.h>

#include "ui_look.hpp"

namespace meshstep::viewer {

inline constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                                ImGuiWindowFlags_NoBringToFrontOnFocus;

// Headings (the step, the algorithm's name, keys) and quieter text (a reference): light blue
// and grey on the dark panels; dark blue and dark grey on the high-contrast theme's white,
// where the light ones would vanish on a projector.
inline ImVec4 heading_color() {
  return current_ui_look().theme == scene::Theme::high_contrast ? ImVec4(0.0f, 0.22f, 0.55f, 1.0f)
                                                                : ImVec4(0.55f, 0.75f, 1.0f, 1.0f);
}
inline ImVec4 quiet_text_color() {
  return current_ui_look().theme == scene::Theme::high_contrast ? ImVec4(0.25f, 0.25f, 0.25f, 1.0f)
                                                                : ImVec4(0.6f, 0.6f, 0.6f, 1.0f);
}

inline void place(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
}

}  // namespace meshstep::viewer
