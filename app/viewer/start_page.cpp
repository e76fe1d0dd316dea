#include "start_page.hpp"

#include <utility>

#include <imgui.h>

#include <filesystem>
#include <vector>

#include "file_dialog.hpp"
#include "keys.hpp"

namespace meshstep::viewer {

namespace {

// The start page's refinement buttons: an algorithm to 30 degrees.
RefineOptions thirty_degrees(const char* algorithm) {
  RefineOptions r;
  r.operation = parse_operation("refine --algorithm " + std::string(algorithm) + " --min-angle 30");
  return r;
}

}  // namespace

namespace {
bool g_wants_new = false;  // the New input button, clicked this frame
}  // namespace

void draw_start_page(int width, int height, const Settings* settings, std::string& picked, RefineOptions& refine) {
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(width), static_cast<float>(height)));
  ImGui::Begin("start", nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "meshstep view");
  ImGui::TextWrapped(
      "Watch a triangulation or a refinement step by step: pick an example, a recent file, or drop a replay log, "
      "a mesh or a .poly/.node input on this window.");
  ImGui::Separator();

  static const std::vector<Example> examples = bundled_examples();
  ImGui::Text("Examples");
  if (examples.empty()) ImGui::TextDisabled("(the folder assets/examples was not found)");
  for (const Example& e : examples) {
    ImGui::PushID(e.path.c_str());
    const std::string name = std::filesystem::path(e.path).filename().string();
    if (ImGui::Button("refine (off-center, 30\u00B0)")) {
      picked = e.path;
      refine = thirty_degrees("offcenter");
    }
    ImGui::SameLine();
    if (ImGui::Button("Lepp-centroid")) {
      picked = e.path;
      refine = thirty_degrees("lepp-centroid");
    }
    ImGui::SameLine();
    if (ImGui::Button("triangulate")) {
      picked = e.path;
      refine = RefineOptions{};
    }
    ImGui::SameLine();
    ImGui::Text("%s", name.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%s", e.description.c_str());
    ImGui::PopID();
  }

  ImGui::Separator();
  ImGui::Text("Recent files");
  if (!settings || settings->recent_files.empty()) ImGui::TextDisabled("(none yet)");
  if (settings)
    for (const std::string& path : settings->recent_files) {
      ImGui::PushID(path.c_str());
      if (ImGui::Button("open")) {
        picked = path;
        refine = RefineOptions{};
      }
      ImGui::SameLine();
      ImGui::TextUnformatted(path.c_str());
      ImGui::PopID();
    }

  ImGui::Separator();
  static char path[1024] = "";
  ImGui::Text("Open a file");
  ImGui::SetNextItemWidth(std::max(200.0f, static_cast<float>(width) - 160.0f));
  const bool entered =
      ImGui::InputTextWithHint("##path", "a replay log, a mesh PREFIX, or a .poly/.node", path, sizeof path,
                               ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("open##path") || entered) && path[0] != '\0') {
    picked = path;
    refine = RefineOptions{};
  }
  // Or look for it: the file dialog (drawn over this page by the window; its pick opens as
  // these do). Its key works here too, though the page has no viewer to run the key table.
  const Chord open = open_file_chord();
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::Button("Open... (Ctrl+O)") ||
      (ImGui::IsKeyPressed(open.key, false) && io.KeyCtrl == open.ctrl && io.KeyShift == open.shift))
    request_file_dialog();
  // Or draw one: an empty input in the workbench (the loop hears Ctrl+N here too).
  ImGui::SameLine();
  if (ImGui::Button("New input (Ctrl+N)")) g_wants_new = true;
  ImGui::End();
}

bool start_page_wants_new() { return std::exchange(g_wants_new, false); }

void draw_problem(std::string& problem, const char* title, bool at_top) {
  const ImGuiIO& io = ImGui::GetIO();
  // At the top, centred over the canvas, left of the side panel (about 30% of the width).
  const ImVec2 where = at_top ? ImVec2(io.DisplaySize.x * 0.35f, 40.0f) : ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y - 20.0f);
  ImGui::SetNextWindowPos(where, ImGuiCond_Always, ImVec2(0.5f, at_top ? 0.0f : 1.0f));
  ImGui::SetNextWindowBgAlpha(0.95f);
  bool open = true;
  ImGui::Begin(title, &open,
               ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
  ImGui::PushTextWrapPos(io.DisplaySize.x * (at_top ? 0.6f : 0.7f));
  ImGui::TextUnformatted(problem.c_str());
  ImGui::PopTextWrapPos();
  ImGui::End();
  if (!open) problem.clear();
}

}  // namespace meshstep::viewer
