// The file dialog on screen: a modal popup over the start page or the viewer, drawn with
// ImGui from the model in file_dialog.hpp. The path field shows the folder and takes a
// typed path (Enter opens it); the list shows the folder's entries with their sizes (a
// double click opens one); Open, Cancel, and Escape closes.
#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <optional>

#include "file_dialog.hpp"

namespace meshstep::viewer {

namespace {

constexpr const char* kTitle = "Open a file";
const ImVec4 kFolderColor(0.55f, 0.75f, 1.0f, 1.0f);
const ImVec4 kMessageColor(0.94f, 0.62f, 0.0f, 1.0f);  // Okabe-Ito orange

// The window's one dialog (see file_dialog.hpp for why it is the window's).
struct DialogState {
  bool requested = false, open = false;
  std::optional<FileDialog> model;
  char path[4096] = "";       // the path field: the folder, or what is being typed
  std::string shown_folder;   // the folder the field and the list show
  int selected = -1;          // in the list, or -1
  bool focus_path = false;    // give the path field the keyboard on the next frame
};

DialogState& dialog() {
  static DialogState state;
  return state;
}

// After a move: the field shows the new folder (selected whole, so that typing replaces it),
// and nothing in the list is selected.
void show_folder(DialogState& d) {
  if (d.model->folder() == d.shown_folder) return;
  d.shown_folder = d.model->folder();
  const std::size_t n = std::min(d.shown_folder.size(), sizeof d.path - 1);
  std::memcpy(d.path, d.shown_folder.data(), n);
  d.path[n] = '\0';
  d.selected = -1;
  d.focus_path = true;
}

// The list of entries: name, kind, size; returns the file chosen by a double click.
std::optional<std::string> draw_entries(DialogState& d, float height) {
  std::optional<std::string> chosen;
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersOuter |
                                ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("##entries", 3, flags, ImVec2(0.0f, height))) return chosen;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableSetupColumn("kind");
  ImGui::TableSetupColumn("size", ImGuiTableColumnFlags_WidthFixed, 90.0f);
  ImGui::TableHeadersRow();
  const std::vector<FileEntry>& entries = d.model->entries();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const FileEntry& e = entries[i];
    const bool folder = e.kind == FileEntry::Kind::folder;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::PushID(static_cast<int>(i));
    const bool clicked = ImGui::Selectable("##row", d.selected == static_cast<int>(i),
                                           ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowDoubleClick);
    ImGui::PopID();
    ImGui::SameLine();
    if (folder) ImGui::TextColored(kFolderColor, "%s/", e.name.c_str());
    else ImGui::TextUnformatted(e.name.c_str());
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%s", describe(e.kind));
    ImGui::TableNextColumn();
    if (!folder) {
      char size[32];
      format_size(e.bytes, size, sizeof size);
      ImGui::TextUnformatted(size);
    }
    if (clicked) {
      d.selected = static_cast<int>(i);
      // A double click opens: a file is chosen, a folder replaces the list (drawn next frame).
      if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
        chosen = d.model->activate(i);
        break;
      }
    }
  }
  ImGui::EndTable();
  return chosen;
}

}  // namespace

void request_file_dialog() {
  if (!dialog().open) dialog().requested = true;
}

void draw_file_dialog(std::string_view open_file, std::string& picked) {
  DialogState& d = dialog();
  if (!d.requested && !d.open) return;  // closed: nothing drawn, nothing allocated
  if (d.requested) {
    d.requested = false;
    d.open = true;
    d.model.emplace(FileDialog::start_folder(std::string(open_file)));
    d.shown_folder.clear();
    show_folder(d);
    ImGui::OpenPopup(kTitle);
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(780.0f, display.x * 0.9f), std::min(520.0f, display.y * 0.85f)),
                           ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0f);  // the list must not be read against the canvas
  bool keep_open = true;
  if (!ImGui::BeginPopupModal(kTitle, &keep_open, ImGuiWindowFlags_NoSavedSettings)) {
    d.open = false;  // closed by its title bar's button
    return;
  }
  FileDialog& model = *d.model;
  std::optional<std::string> chosen;
  bool close = false;

  // The folder, as a field to type a path in, with the way up and the hidden files' switch.
  if (ImGui::Button("Up")) model.go_up();
  ImGui::SameLine();
  const float hidden_width = ImGui::CalcTextSize("hidden").x + ImGui::GetFrameHeight() + 16.0f;
  ImGui::SetNextItemWidth(std::max(120.0f, ImGui::GetContentRegionAvail().x - hidden_width));
  if (d.focus_path) {
    ImGui::SetKeyboardFocusHere();
    d.focus_path = false;
  }
  if (ImGui::InputText("##path", d.path, sizeof d.path,
                       ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
    chosen = model.submit(d.path);
    if (!chosen && model.folder() == d.shown_folder) d.focus_path = true;  // not a path: type again
  }
  ImGui::SameLine();
  bool hidden = model.show_hidden();
  if (ImGui::Checkbox("hidden", &hidden)) {
    model.set_show_hidden(hidden);
    d.selected = -1;
  }
  if (!model.message().empty()) ImGui::TextColored(kMessageColor, "%s", model.message().c_str());

  // The entries, leaving room for the buttons below.
  const float buttons = ImGui::GetFrameHeightWithSpacing() + ImGui::GetStyle().ItemSpacing.y;
  if (!chosen) chosen = draw_entries(d, std::max(60.0f, ImGui::GetContentRegionAvail().y - buttons));

  if (ImGui::Button("Open", ImVec2(90.0f, 0.0f)) && !chosen)
    chosen = d.selected >= 0 ? model.activate(static_cast<std::size_t>(d.selected)) : model.submit(d.path);
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(90.0f, 0.0f))) close = true;
  ImGui::SameLine();
  const std::size_t n = model.entries().size();
  ImGui::TextDisabled("%zu %s; Enter opens the typed path, Escape closes", n, n == 1 ? "entry" : "entries");
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) close = true;

  show_folder(d);  // after a move into a folder, up, or to a typed folder
  if (chosen) {
    picked = *chosen;
    close = true;
  }
  if (close) {
    ImGui::CloseCurrentPopup();
    d.open = false;
  }
  ImGui::EndPopup();
}

}  // namespace meshstep::viewer
