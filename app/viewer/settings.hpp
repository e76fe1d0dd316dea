// The viewer's settings: window size, layout, which panels are open, the drawing and playback
// options and the recent files, kept from one run to the next in one text file in the user's
// config folder. No GL and no ImGui: the viewer copies them in at start and out at exit.
//
// The file is `key = value` lines (a `#` line is a comment), for example
//
//   # meshstep viewer settings, written by meshstep-view
//   window_width = 1280
//   window_height = 800
//   side_panel_width = 380
//   ui_scale = 1.5
//   explain_open = true
//   ...
//   color_by = quality
//   theme = dark            (light, dark, high-contrast)
//   layers = fill, edges, segments
//   speed = 4
//   unit = step
//   follow = false
//   timeline_marks = splits, rejected
//   view_3d = true
//   azimuth = -60
//   elevation = 35
//   z_scale = 2
//   recent = /home/me/runs/square log.msl
//   recent = /home/me/runs/key.msl
//
// Values are the rest of the line, trimmed. `recent` repeats, most recent first. A path that
// would not survive the trimming (leading or trailing blanks, control characters such as a
// newline, a leading double quote, or empty) is written in double quotes with C escapes
// (\\ \" \n \r \t \xHH).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "meshstep/scene/scene.hpp"
#include "session.hpp"
#include "timeline_marks.hpp"
#include "view_3d.hpp"

namespace meshstep::viewer {

struct Settings {
  static constexpr int kMinWindow = 320, kMaxWindow = 8192;
  static constexpr float kMinSidePanel = 200.0f, kMaxSidePanel = 1200.0f;
  static constexpr std::size_t kMaxRecent = 10;

  int window_width = 1280, window_height = 800;
  float side_panel_width = 380.0f;  // layout, at UI scale 1
  float ui_scale = 1.0f;            // kMinUiScale..kMaxUiScale in steps of kUiScaleStep (ui_look.hpp)
  // Which panels are open.
  bool explain_open = true, layers_open = true, stats_open = true, code_open = true, plots_open = false;
  scene::ColorBy color_by = scene::ColorBy::none;
  scene::Theme theme = scene::Theme::light;
  scene::LayerSet layers = scene::LayerSet::standard();
  double speed = 4.0;  // Playback::kMinSpeed..Playback::kMaxSpeed
  Unit unit = Unit::step;
  bool follow = false;
  MarkSet timeline_marks = MarkSet::defaults();  // the kinds the timeline marks
  // A terrain's run is seen in 3D (logs without heights stay 2D), from this orbit.
  bool view_3d = false;
  Orbit orbit;
  std::vector<std::string> recent_files;  // most recent first, at most kMaxRecent, no duplicates

  // Puts `path` first (moving it there if it is already in the list) and drops the oldest
  // beyond kMaxRecent. Paths are compared as given: pass them absolute. Ignores "".
  void add_recent(const std::string& path);

  friend bool operator==(const Settings&, const Settings&) = default;
};

// Where the settings live: $MESHSTEP_VIEWER_CONFIG when set (the whole path: for tests, and a
// way to keep several setups), else $XDG_CONFIG_HOME/meshstep/viewer.ini (XDG_CONFIG_HOME
// absolute), else $HOME/.config/meshstep/viewer.ini. Empty when none of these is set: there
// is nowhere to keep settings, and the viewer should neither load nor save them.
std::string settings_path();

// Reads the file. Missing: the defaults and no warning. Damaged: the good lines are kept and
// each problem (a line that is not `key = value`, an unknown key, a bad or out-of-range
// value) leaves its field at the default, with one warning "PATH:LINE: what is wrong; using
// the default" appended to `warnings`. A file that cannot be read at all (a folder, no
// permission, far too large) gives the defaults and one warning "PATH: ...". When a key is
// given twice the later line wins. Never throws for the file's contents.
Settings load_settings(const std::string& path, std::vector<std::string>& warnings);

// Writes the file atomically (a reader never sees half of it, and a failure leaves the old
// file as it was), creating its folder when missing. Throws InputError("PATH: why").
void save_settings(const Settings& settings, const std::string& path);

// The file's text, as save_settings writes it.
std::string format_settings(const Settings& settings);

}  // namespace meshstep::viewer
