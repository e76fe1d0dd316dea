#include "keys.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <vector>

#include "edit_keys.hpp"
#include "file_dialog.hpp"
#include "teach_script.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

namespace {

using replay::StepKind;
using scene::Layer;

std::vector<KeyAction> make_actions() {
  std::vector<KeyAction> a;
  const auto add = [&](Chord chord, const char* keys, const char* what, std::function<void(Viewer&)> run) {
    a.push_back({chord, keys, what, std::move(run)});
  };
  add({GLFW_KEY_SPACE}, "Space", "play / pause", [](Viewer& v) { v.session().toggle_play(); });
  add({GLFW_KEY_RIGHT}, "Right", "next step", [](Viewer& v) { v.session().move(Unit::step, +1); });
  add({GLFW_KEY_LEFT}, "Left", "previous step", [](Viewer& v) { v.session().move(Unit::step, -1); });
  add({GLFW_KEY_RIGHT, true}, "Shift+Right", "next event", [](Viewer& v) { v.session().move(Unit::event, +1); });
  add({GLFW_KEY_LEFT, true}, "Shift+Left", "previous event", [](Viewer& v) { v.session().move(Unit::event, -1); });
  add({GLFW_KEY_PAGE_DOWN}, "Page Down", "next phase boundary", [](Viewer& v) { v.session().move(Unit::phase, +1); });
  add({GLFW_KEY_PAGE_UP}, "Page Up", "previous phase boundary", [](Viewer& v) { v.session().move(Unit::phase, -1); });
  add({GLFW_KEY_HOME}, "Home", "start of the run", [](Viewer& v) { v.session().to_start(); });
  add({GLFW_KEY_END}, "End", "end of the run", [](Viewer& v) { v.session().to_end(); });
  add({GLFW_KEY_S}, "S", "next segment split", [](Viewer& v) { v.session().find_step(StepKind::split_segment, +1); });
  add({GLFW_KEY_S, true}, "Shift+S", "previous segment split",
      [](Viewer& v) { v.session().find_step(StepKind::split_segment, -1); });
  add({GLFW_KEY_R}, "R", "next refinement step", [](Viewer& v) { v.session().find_step(StepKind::refine, +1); });
  add({GLFW_KEY_R, true}, "Shift+R", "previous refinement step",
      [](Viewer& v) { v.session().find_step(StepKind::refine, -1); });
  add({GLFW_KEY_J}, "J", "next rejected point (it encroached a segment)",
      [](Viewer& v) { v.session().find_event(is_rejected_point, +1); });
  add({GLFW_KEY_J, true}, "Shift+J", "previous rejected point",
      [](Viewer& v) { v.session().find_event(is_rejected_point, -1); });
  add({GLFW_KEY_K}, "K", "next cavity of more than 10 faces",
      [](Viewer& v) { v.session().find_event(is_big_cavity, +1); });
  add({GLFW_KEY_K, true}, "Shift+K", "previous cavity of more than 10 faces",
      [](Viewer& v) { v.session().find_event(is_big_cavity, -1); });
  // "+" is Shift+= on most keyboards (and its own key on the keypad); "=" does the same, so
  // that the key works with or without Shift.
  add({GLFW_KEY_EQUAL, true}, "+", "play twice as fast", [](Viewer& v) { v.session().scale_speed(2.0); });
  add({GLFW_KEY_EQUAL}, "=", nullptr, [](Viewer& v) { v.session().scale_speed(2.0); });
  add({GLFW_KEY_KP_ADD}, "kp+", nullptr, [](Viewer& v) { v.session().scale_speed(2.0); });
  add({GLFW_KEY_MINUS}, "-", "play half as fast", [](Viewer& v) { v.session().scale_speed(0.5); });
  add({GLFW_KEY_KP_SUBTRACT}, "kp-", nullptr, [](Viewer& v) { v.session().scale_speed(0.5); });
  add({GLFW_KEY_U}, "U", "play by events / steps / phases", [](Viewer& v) {
    Playback& p = v.session().playback();
    p.unit = p.unit == Unit::event ? Unit::step : p.unit == Unit::step ? Unit::phase : Unit::event;
  });
  add({GLFW_KEY_N}, "N", "next stop of the tour, or the quiz's next question", [](Viewer& v) { next_key(v); });
  add({GLFW_KEY_P}, "P", "previous stop of the tour", [](Viewer& v) { previous_key(v); });
  add({GLFW_KEY_G}, "G", "quiz: predict the next step (on / off)", [](Viewer& v) { quiz_key(v); });
  add({GLFW_KEY_F}, "F", "fit the run in view", [](Viewer& v) { v.request_fit(); });
  add({GLFW_KEY_D}, "D", "difference overlay (runs side by side)", [](Viewer& v) { v.toggle_difference(); });
  add({GLFW_KEY_L}, "L", "follow the current step while playing", [](Viewer& v) { v.follow = !v.follow; });
  add({GLFW_KEY_C}, "C", "next colouring", [](Viewer& v) { v.cycle_color_by(+1); });
  add({GLFW_KEY_C, true}, "Shift+C", "previous colouring", [](Viewer& v) { v.cycle_color_by(-1); });
  add({GLFW_KEY_T}, "T", "light / dark theme", [](Viewer& v) {
    Session& s = v.session();
    s.set_theme(s.options().theme == scene::Theme::light ? scene::Theme::dark : scene::Theme::light);
  });
  add({GLFW_KEY_T, true}, "Shift+T", "high-contrast theme (a projector) / light", [](Viewer& v) { v.toggle_high_contrast(); });
  // Presentation: the UI scale (fonts rasterised again at the new size), full screen, and
  // the canvas alone. F11 is full screen as in most programs; the legend's layer is on F12.
  add({GLFW_KEY_EQUAL, false, true}, "Ctrl+=", "larger UI (text and panels)", [](Viewer& v) { v.scale_ui(+1); });
  add({GLFW_KEY_EQUAL, true, true}, "Ctrl+Shift+=", nullptr, [](Viewer& v) { v.scale_ui(+1); });
  add({GLFW_KEY_MINUS, false, true}, "Ctrl+-", "smaller UI", [](Viewer& v) { v.scale_ui(-1); });
  add({GLFW_KEY_F11}, "F11", "full screen / window", [](Viewer& v) { v.full_screen = !v.full_screen; });
  add({GLFW_KEY_TAB}, "Tab", "hide / show the panels (the canvas fills the window)",
      [](Viewer& v) { v.panels_hidden = !v.panels_hidden; });
  // The 3D view of a terrain's run (view_3d.hpp). Ctrl and the arrows turn it (the arrows
  // alone step through the run); Z stretches the heights, as terrain is often flat.
  add({GLFW_KEY_V}, "V", "2D / 3D view (a terrain's run)", [](Viewer& v) { v.set_view_3d(!v.view_3d()); });
  add({GLFW_KEY_LEFT, false, true}, "Ctrl+Left", "3D: azimuth -15\u00B0", [](Viewer& v) { v.turn_orbit(-15.0, 0.0); });
  add({GLFW_KEY_RIGHT, false, true}, "Ctrl+Right", "3D: azimuth +15\u00B0", [](Viewer& v) { v.turn_orbit(15.0, 0.0); });
  add({GLFW_KEY_UP, false, true}, "Ctrl+Up", "3D: elevation +5\u00B0 (more from above)",
      [](Viewer& v) { v.turn_orbit(0.0, 5.0); });
  add({GLFW_KEY_DOWN, false, true}, "Ctrl+Down", "3D: elevation -5\u00B0", [](Viewer& v) { v.turn_orbit(0.0, -5.0); });
  add({GLFW_KEY_Z}, "Z", "3D: heights twice as high", [](Viewer& v) { v.scale_heights(2.0); });
  add({GLFW_KEY_Z, true}, "Shift+Z", "3D: heights half as high", [](Viewer& v) { v.scale_heights(0.5); });
  // Layers on F2..F10 and F12 (F11 is full screen), in the scene's layer order; the Voronoi
  // diagram, off unless a lecture asks for it, on Shift+V beside them.
  static const std::array<std::string, scene::kLayerCount> kLayerTexts = [] {
    std::array<std::string, scene::kLayerCount> t;
    for (std::size_t i = 0; i < scene::kLayerCount; ++i) t[i] = std::string("layer: ") + scene::name(Layer(i));
    return t;
  }();
  static constexpr std::array<const char*, 10> kLayerKeys = {"F2", "F3", "F4", "F5", "F6", "F7", "F8", "F9", "F10", "F12"};
  std::size_t function_key = 0;
  for (std::size_t i = 0; i < scene::kLayerCount; ++i) {
    const auto layer = static_cast<Layer>(i);
    const auto toggle = [layer](Viewer& v) { v.toggle_layer(layer); };
    if (layer == Layer::voronoi) {
      add({GLFW_KEY_V, true}, "Shift+V", kLayerTexts[i].c_str(), toggle);
      continue;
    }
    const std::size_t k = function_key++;
    add({GLFW_KEY_F2 + static_cast<int>(k) + (k >= 9 ? 1 : 0)}, kLayerKeys.at(k), kLayerTexts[i].c_str(), toggle);
  }
  static constexpr std::array<const char*, 9> kDigits = {"1", "2", "3", "4", "5", "6", "7", "8", "9"};
  static constexpr std::array<const char*, 9> kCtrlDigits = {"Ctrl+1", "Ctrl+2", "Ctrl+3", "Ctrl+4", "Ctrl+5",
                                                             "Ctrl+6", "Ctrl+7", "Ctrl+8", "Ctrl+9"};
  for (int slot = 1; slot <= 9; ++slot) {
    add({GLFW_KEY_0 + slot}, kDigits[slot - 1], slot == 1 ? "go to bookmark 1-9" : nullptr,
        [slot](Viewer& v) { v.session().go_to_bookmark(slot); });
    add({GLFW_KEY_0 + slot, false, true}, kCtrlDigits[slot - 1], slot == 1 ? "set bookmark 1-9 here" : nullptr,
        [slot](Viewer& v) { v.session().set_bookmark(slot); });
  }
  add({GLFW_KEY_SLASH, true}, "?", "this list of keys", [](Viewer& v) { v.help_open = !v.help_open; });
  add({GLFW_KEY_F1}, "F1", "this list of keys", [](Viewer& v) { v.help_open = !v.help_open; });
  add({GLFW_KEY_ESCAPE}, "Esc", "close this list", [](Viewer& v) { v.help_open = false; });
  // The workbench (edit_keys.hpp): the input edited and re-meshed at once.
  add({GLFW_KEY_E}, "E", "edit mode: edit the input, re-meshed at each edit", [](Viewer& v) { edit_key(v, EditKey::toggle); });
  add({GLFW_KEY_N, false, true}, "Ctrl+N", "new input (empty), in edit mode", [](Viewer& v) { edit_key(v, EditKey::new_input); });
  add({GLFW_KEY_S, false, true}, "Ctrl+S", "save the input (.poly)", [](Viewer& v) { edit_key(v, EditKey::save); });
  add({GLFW_KEY_Z, false, true}, "Ctrl+Z", "undo an edit", [](Viewer& v) { edit_key(v, EditKey::undo); });
  add({GLFW_KEY_Z, true, true}, "Ctrl+Shift+Z", "redo an edit", [](Viewer& v) { edit_key(v, EditKey::redo); });
  add({GLFW_KEY_Y, false, true}, "Ctrl+Y", "redo an edit", [](Viewer& v) { edit_key(v, EditKey::redo); });
  add({GLFW_KEY_DELETE}, "Delete", "edit mode: delete the selected element", [](Viewer& v) { edit_key(v, EditKey::erase); });
  add({GLFW_KEY_B}, "B", "edit mode: refine a region: drag a box", [](Viewer& v) { edit_key(v, EditKey::region_box); });
  add({GLFW_KEY_B, true}, "Shift+B", "edit mode: refine a region: draw a lasso",
      [](Viewer& v) { edit_key(v, EditKey::region_lasso); });
  add(open_file_chord(), "Ctrl+O", "open a file (a dialog)", [](Viewer&) { request_file_dialog(); });
  add({GLFW_KEY_Q, false, true}, "Ctrl+Q", "quit", [](Viewer& v) { v.quit_requested = true; });
  return a;
}

struct Named {
  const char* name;
  int key;
};

constexpr Named kNamedKeys[] = {
    {"space", GLFW_KEY_SPACE},   {"right", GLFW_KEY_RIGHT},       {"left", GLFW_KEY_LEFT},
    {"up", GLFW_KEY_UP},         {"down", GLFW_KEY_DOWN},         {"pagedown", GLFW_KEY_PAGE_DOWN},
    {"pageup", GLFW_KEY_PAGE_UP}, {"home", GLFW_KEY_HOME},        {"page down", GLFW_KEY_PAGE_DOWN},
    {"page up", GLFW_KEY_PAGE_UP},        {"end", GLFW_KEY_END},
    {"escape", GLFW_KEY_ESCAPE}, {"esc", GLFW_KEY_ESCAPE},        {"enter", GLFW_KEY_ENTER},
    {"tab", GLFW_KEY_TAB},       {"kp+", GLFW_KEY_KP_ADD},        {"=", GLFW_KEY_EQUAL},
    {"kp-", GLFW_KEY_KP_SUBTRACT},
    {"-", GLFW_KEY_MINUS},       {"/", GLFW_KEY_SLASH},           {"backspace", GLFW_KEY_BACKSPACE},
    {"delete", GLFW_KEY_DELETE},
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

Chord open_file_chord() { return {GLFW_KEY_O, false, true}; }

std::span<const KeyAction> key_actions() {
  static const std::vector<KeyAction> actions = make_actions();
  return actions;
}

std::optional<Chord> parse_chord(std::string_view text) {
  Chord chord;
  std::string rest = lower(text);
  // Modifiers first: "shift+", "ctrl+" (a lone "+" is the key itself).
  for (bool more = true; more && rest.size() > 1;) {
    more = false;
    if (rest.starts_with("shift+")) chord.shift = more = true, rest.erase(0, 6);
    else if (rest.starts_with("ctrl+")) chord.ctrl = more = true, rest.erase(0, 5);
  }
  // The shifted keys, as a keyboard types them: "?" is Shift+/, "+" is Shift+=.
  if (rest == "?") return Chord{GLFW_KEY_SLASH, true, chord.ctrl};
  if (rest == "+") return Chord{GLFW_KEY_EQUAL, true, chord.ctrl};
  for (const Named& n : kNamedKeys)
    if (rest == n.name) {
      chord.key = n.key;
      return chord;
    }
  if (rest.size() == 1 && std::isalnum(static_cast<unsigned char>(rest[0]))) {
    chord.key = std::isdigit(static_cast<unsigned char>(rest[0])) ? GLFW_KEY_0 + (rest[0] - '0')
                                                                   : GLFW_KEY_A + (rest[0] - 'a');
    return chord;
  }
  if (rest.size() >= 2 && rest[0] == 'f') {
    int n = 0;
    for (std::size_t i = 1; i < rest.size(); ++i) {
      if (!std::isdigit(static_cast<unsigned char>(rest[i]))) return std::nullopt;
      n = n * 10 + (rest[i] - '0');
    }
    if (n >= 1 && n <= 12) {
      chord.key = GLFW_KEY_F1 + n - 1;
      return chord;
    }
  }
  return std::nullopt;
}

}  // namespace meshstep::viewer
