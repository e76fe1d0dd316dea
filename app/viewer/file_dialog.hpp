// The file dialog's model: one folder's listing, limited to what the viewer opens, and the
// moves a person makes in it. No GL and no ImGui (file_dialog_panel.cpp draws it); nothing
// here throws for the file system: a folder that is missing or cannot be read leaves the
// dialog where it was, with a message saying why.
//
// What is listed: folders, then files, each sorted by name (ignoring case); files only of
// the kinds the viewer opens: replay logs (*.mslog), inputs (*.poly, *.node) and meshes. A
// mesh is a PREFIX.node beside a PREFIX.ele; it is listed once, by its PREFIX (the name
// without an extension, the way `meshstep view` takes it), and that .node is not listed
// again as an input (type its name to triangulate it instead). Hidden names (a leading dot)
// are left out unless asked for.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace meshstep::viewer {

struct FileEntry {
  enum class Kind { folder, log, input, mesh };
  Kind kind = Kind::folder;
  std::string name;  // as listed: "lesson.poly", "out" (a mesh PREFIX), "runs" (a folder)
  std::string path;  // what opening it opens (a mesh: its PREFIX)
  std::uintmax_t bytes = 0;  // a file's size; a mesh's .node and .ele together; a folder 0
};

// "log", "input", "mesh (.node + .ele)", "folder".
const char* describe(FileEntry::Kind kind);
// "812 B", "12.4 KiB", "3.1 MiB", "1.2 GiB"; written into `out` (no allocation).
void format_size(std::uintmax_t bytes, char* out, std::size_t size);

class FileDialog {
 public:
  // Lists `folder` ("" or one that cannot be listed: the current folder).
  explicit FileDialog(const std::string& folder = "");

  // The folder to start in for a file open now ("" for none): the file's folder, else the
  // current folder.
  static std::string start_folder(const std::string& open_file);

  const std::string& folder() const { return folder_; }  // absolute, without a trailing '/'
  const std::vector<FileEntry>& entries() const { return entries_; }
  // Why the last move failed ("" when it did not).
  const std::string& message() const { return message_; }

  // Goes to a folder (relative to the current one); false, staying put, with message() set
  // when it is missing or cannot be read.
  bool go_to(const std::string& folder);
  // To the folder above (false at the root).
  bool go_up();
  // Lists the folder again (after a change of show_hidden, or of the folder itself).
  void refresh();

  bool show_hidden() const { return show_hidden_; }
  void set_show_hidden(bool on);

  // Opens entries()[index]: a folder is gone into (nullopt); a file is picked (its path).
  std::optional<std::string> activate(std::size_t index);
  // What a typed path means (relative to the current folder; "~" is the home folder): a
  // folder is gone into (nullopt), an existing file or a mesh PREFIX is picked (its absolute
  // path); anything else leaves the dialog as it is, with message() saying why.
  std::optional<std::string> submit(const std::string& typed);

 private:
  // Lists `folder` into the listing; false (and nothing changed) when it cannot.
  bool list(const std::string& folder);
  std::string resolve(const std::string& typed) const;

  std::string folder_;
  std::vector<FileEntry> entries_;
  std::string message_;
  bool show_hidden_ = false;
};

// The dialog on screen (file_dialog_panel.cpp). It belongs to the window, not to a viewer:
// it opens from the start page as from a run, and it outlives the viewer it was opened from
// (a pick replaces that viewer), so its state is the window's, in that file.
//
// Asks for the dialog; it opens at the next draw_file_dialog.
void request_file_dialog();
// Draws the dialog while it is open (a modal popup). `open_file`: the file shown now ("" for
// none), whose folder it starts in. When a file is chosen, sets `picked` to it (the window
// then opens it as it opens a file picked on the start page) and closes.
void draw_file_dialog(std::string_view open_file, std::string& picked);

}  // namespace meshstep::viewer
