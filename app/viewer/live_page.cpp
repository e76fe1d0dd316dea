#include "live_page.hpp"

#include <imgui.h>

#include <cstdio>

#include "panel_style.hpp"

namespace meshstep::viewer {

namespace {

constexpr float kHeader = 64.0f;
constexpr double kPicturesPerSecond = 4.0;  // how often the log so far is read again

}  // namespace

void draw_live_page(LiveView& live, int width, int height) {
  LiveRun& run = *live.run;
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  place(0, 0, w, h);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(10, 8));
  ImGui::Begin("live run", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  const bool going = run.running();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", run.command().c_str());
  ImGui::SameLine();
  if (ImGui::Button("Cancel (Esc)") || (!ImGui::GetIO().WantCaptureKeyboard && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)))
    run.cancel();
  const CanvasPicture& p = live.picture;
  if (live.opening) {
    ImGui::Text("ran %.1f s \u00B7 opening its log%s", run.seconds(),
                live.has_picture ? " (the canvas shows the mesh the run wrote last)" : "");
  } else if (live.has_picture) {
    ImGui::Text("%s %.1f s \u00B7 the mesh so far: %zu triangles \u00B7 %s", going ? "running for" : "ran", run.seconds(),
                p.moment.scene.mesh.triangles.size(), p.moment.explanation.heading.c_str());
  } else {
    ImGui::Text("%s %.1f s \u00B7 waiting for the first part of its log", going ? "running for" : "ran", run.seconds());
  }

  // The mesh at the end of what the run has written, fitted to the canvas.
  const int cw = std::max(64, width - 20), ch = std::max(64, height - static_cast<int>(kHeader) - 10);
  CanvasRequest wanted;
  wanted.position = UINT64_MAX;
  wanted.fit = true;
  wanted.width = cw;
  wanted.height = ch;
  wanted.generation = static_cast<std::uint32_t>(run.seconds() * kPicturesPerSecond);
  live.run->preview().request(wanted);
  if (live.run->preview().take(live.picture)) {
    live.texture.upload(live.picture.image);
    live.has_picture = true;
    ++live.pictures;
  }
  ImGui::SetCursorPos(ImVec2(10, kHeader));
  if (live.has_picture) ImGui::Image(live.texture.id(), ImVec2(static_cast<float>(cw), static_cast<float>(ch)));
  ImGui::End();
  ImGui::PopStyleVar();
  (void)h;
}

std::string live_state_json(LiveView& live) {
  LiveRun& run = *live.run;
  char text[512];
  std::snprintf(text, sizeof text,
                "{\n  \"page\": \"live\",\n  \"running\": %s,\n  \"seconds\": %.3f,\n  \"pictures\": %zu,\n"
                "  \"picture_triangles\": %zu\n}\n",
                run.running() ? "true" : "false", run.seconds(), live.pictures,
                live.has_picture ? live.picture.moment.scene.mesh.triangles.size() : std::size_t{0});
  return text;
}

}  // namespace meshstep::viewer
