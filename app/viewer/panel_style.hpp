// What the viewer's fixed panels share: they neither move, resize, collapse nor keep ImGui
// settings (the viewer lays them out every frame), and are placed before they begin.
#pragma once

#include <imgui.h>

namespace meshstep::viewer {

inline constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                                ImGuiWindowFlags_NoBringToFrontOnFocus;

inline void place(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
}

}  // namespace meshstep::viewer
