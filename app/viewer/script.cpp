#include "script.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "edit_script.hpp"
#include "compare_sync.hpp"
#include "keys.hpp"
#include "teach_script.hpp"
#include "meshstep/error.hpp"
#include "meshstep/scene/scene.hpp"
#include "timeline_marks.hpp"
#include "ui_look.hpp"

namespace meshstep::viewer {

namespace {

bool is_number(const std::string& s, bool allow_sign, bool allow_point) {
  if (s.empty()) return false;
  std::size_t digits = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c >= '0' && c <= '9') ++digits;
    else if (!((c == '-' || c == '+') && i == 0 && allow_sign) && !(c == '.' && allow_point)) return false;
  }
  return digits > 0;
}

// What is wrong with an action, or "" when nothing is.
std::string check(const ScriptAction& a) {
  const auto& v = a.verb;
  const auto n = a.args.size();
  const auto count = [&](std::size_t want, const char* usage) -> std::string {
    return n == want ? "" : std::string("expected: ") + usage;
  };
  if (v == "seek") {
    if (n == 1 && (a.args[0] == "start" || a.args[0] == "end")) return "";
    if (n == 2 && (a.args[0] == "step" || a.args[0] == "event") && is_number(a.args[1], false, false)) return "";
    return "expected: seek step N | seek event N | seek start | seek end";
  }
  if (v == "frames" || v == "play") {
    if (n == 1 && is_number(a.args[0], false, false)) return "";
    return "expected: " + v + " N (a count of frames)";
  }
  if (v == "key") {
    if (n != 1) return "expected: key CHORD (Space, Shift+Right, Ctrl+3, F2, ?)";
    return parse_chord(a.args[0]) ? "" : "unknown key '" + a.args[0] + "'";
  }
  if (v == "toggle") {
    if (n != 1) return "expected: toggle LAYER";
    return scene::parse_layer(a.args[0]) ? "" : "unknown layer '" + a.args[0] + "'";
  }
  if (v == "color-by") {
    if (n != 1) return "expected: color-by NAME";
    return scene::parse_color_by(a.args[0]) ? "" : "unknown colouring '" + a.args[0] + "'";
  }
  if (v == "speed") {
    if (n == 1 && is_number(a.args[0], false, true)) return "";
    return "expected: speed X (0.25 to 1000)";
  }
  if (v == "unit") {
    if (n == 1 && (a.args[0] == "event" || a.args[0] == "step" || a.args[0] == "phase")) return "";
    return "expected: unit event|step|phase";
  }
  if (v == "view") {
    if (n == 1 && (a.args[0] == "2d" || a.args[0] == "3d")) return "";
    return "expected: view 2d|3d";
  }
  if (v == "orbit") {
    if (n == 2 && is_number(a.args[0], true, true) && is_number(a.args[1], true, true) &&
        std::abs(std::strtod(a.args[1].c_str(), nullptr)) <= 90.0)
      return "";
    return "expected: orbit AZ EL (degrees, the elevation from -90 to 90)";
  }
  if (v == "z-scale") {
    if (n == 1 && is_number(a.args[0], false, true) && std::strtod(a.args[0].c_str(), nullptr) > 0.0) return "";
    return "expected: z-scale K (a number > 0)";
  }
  if (v == "ui-scale") {
    if (n == 1 && parse_ui_scale(a.args[0])) return "";
    return "expected: ui-scale S (0.75 to 3, in steps of 0.25)";
  }
  if (v == "theme") {
    if (n == 1 && parse_theme(a.args[0])) return "";
    return "expected: theme light|dark|high-contrast";
  }
  if (v == "panels") {
    if (n == 1 && (a.args[0] == "show" || a.args[0] == "hide")) return "";
    return "expected: panels show|hide";
  }
  if (v == "full-screen") {
    if (n == 1 && (a.args[0] == "on" || a.args[0] == "off")) return "";
    return "expected: full-screen on|off";
  }
  if (v == "select") {
    if (n == 2 && is_number(a.args[0], true, true) && is_number(a.args[1], true, true)) return "";
    return "expected: select X Y (world coordinates)";
  }
  if (v == "mouse" || v == "drag") {
    if (n == 2 && is_number(a.args[0], true, true) && is_number(a.args[1], true, true)) return "";
    return "expected: " + v + " X Y (pixels)";
  }
  if (v == "drag-path") {
    bool numbers = n >= 2 && n % 2 == 0;
    for (std::size_t i = 0; numbers && i < n; ++i) numbers = is_number(a.args[i], true, true);
    if (numbers) return "";
    return "expected: drag-path DX1 DY1 DX2 DY2 ... (pixels, each move from where the one before ended)";
  }
  if (v == "wait-until") {
    if (n == 2 && is_number(a.args[1], false, true) && std::strtod(a.args[1].c_str(), nullptr) > 0.0) return "";
    return "expected: wait-until FILE SECONDS (frames go on, with the window's own mouse and keys, until FILE exists)";
  }
  if (v == "wait-input") {
    if (n == 1 && is_number(a.args[0], false, true) && std::strtod(a.args[0].c_str(), nullptr) > 0.0) return "";
    return "expected: wait-input SECONDS (frames go on, with the window's own mouse and keys)";
  }
  if (v == "wheel") {
    if (n == 1 && is_number(a.args[0], true, true)) return "";
    return "expected: wheel N";
  }
  if (v == "toggle-marks") {
    if (n != 1) return "expected: toggle-marks KIND";
    if (parse_mark(a.args[0])) return "";
    std::string known;
    for (std::size_t i = 0; i < kMarkCount; ++i) known.append(i ? ", " : "").append(name(static_cast<Mark>(i)));
    return std::string("unknown kind of mark '").append(a.args[0]).append("' (").append(known).append(")");
  }
  if (v == "sync") {
    if (n == 1 && parse_sync_mode(a.args[0])) return "";
    return "expected: sync step|vertices|fraction";
  }
  if (v == "difference") {
    if (n == 1 && (a.args[0] == "on" || a.args[0] == "off")) return "";
    return "expected: difference on|off";
  }
  if (v == "compare-with") return n >= 1 ? "" : "expected: compare-with OPTIONS (as refine takes them: --algorithm NAME ...)";
  if (v == "tour" || v == "quiz") return n == 0 ? "expected: " + v + " and what to do" : check_teaching_action(a);
  if (v == "type") return n == 1 && !a.args[0].empty() ? "" : "expected: type TEXT";
  if (v == "click" || v == "quit" || v == "check" || v == "wait" || v == "settle" || v == "watch") return count(0, v.c_str());
  if (v == "screenshot" || v == "canvas" || v == "state" || v == "peek" || v == "open") return count(1, (v + " FILE").c_str());
  if (is_edit_action(v)) return check_edit_action(a);  // the workbench's (edit_script.hpp)
  return "unknown action '" + v + "'";
}

}  // namespace

std::vector<ScriptAction> read_script(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot read the script");
  std::vector<ScriptAction> actions;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    std::istringstream words(text);
    ScriptAction a;
    a.line = line;
    if (!(words >> a.verb)) continue;
    if (a.verb == "type") {
      // The rest of the line as it is (a path may hold spaces), without the blanks round it.
      std::string rest;
      std::getline(words, rest);
      const std::size_t begin = rest.find_first_not_of(" \t"), end = rest.find_last_not_of(" \t\r");
      if (begin != std::string::npos) a.args.push_back(rest.substr(begin, end - begin + 1));
    } else {
      for (std::string w; words >> w;) a.args.push_back(w);
    }
    if (const std::string why = check(a); !why.empty()) throw InputError(path, line, why);
    actions.push_back(std::move(a));
  }
  return actions;
}

}  // namespace meshstep::viewer
