// Every key of the viewer, in one table: what the key does, the text the `?` overlay shows
// for it, and the name a script presses it by. Keys are GLFW key codes (the codes ImGui's
// io.KeysDown uses in a window, and that the scripted viewer sets off screen).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace meshstep::viewer {

class Viewer;

struct Chord {
  int key = 0;
  bool shift = false, ctrl = false;
  friend bool operator==(const Chord&, const Chord&) = default;
};

struct KeyAction {
  Chord chord;
  const char* keys;  // as the help shows it: "Shift+Right"
  const char* what;  // "next event"
  std::function<void(Viewer&)> run;
};

// The table, in the order the help lists it.
std::span<const KeyAction> key_actions();

// The chord that opens the file dialog: in the table, and heard by the start page too
// (which has no viewer to run the table's actions on).
Chord open_file_chord();

// "Space", "Shift+Right", "ctrl+3", "F2", "?" (case-insensitive), as scripts write keys.
std::optional<Chord> parse_chord(std::string_view text);

}  // namespace meshstep::viewer
