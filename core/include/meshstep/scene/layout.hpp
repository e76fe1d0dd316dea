// Where the parts of a picture that do not move with the world go: the caption band across
// the top and the legend on the right. The GL renderer and the SVG writer both place them
// from this, so the two agree pixel for pixel, and the camera's fit leaves them room.
//
// All in pixels, origin top-left, y down. Text positions are baselines; `anchor_end` text
// ends at its position (right-aligned), other text starts there.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene {

struct Rect {
  double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
};

struct TextSpot {
  Point at;  // baseline
  double size_px = 13.0;
  bool anchor_end = false;
};

struct LegendLayout {
  Rect panel;                   // a translucent backing behind bar, ticks and title
  Rect bar;                     // continuous: the colour bar, its first colour at the bottom
  std::vector<Rect> swatches;   // categorical: one box per colour, top to bottom
  TextSpot title;
  std::vector<double> tick_y;   // continuous: where each tick meets the bar
  std::vector<TextSpot> ticks;  // one per Legend::Tick
  double tick_length = 5.0;     // tick marks run from the bar's right side this far
};

struct Layout {
  std::optional<Rect> caption_band;
  TextSpot caption;
  // A caption too long for the picture even set smaller (a narrow canvas: runs side by side)
  // is wrapped instead: its lines, and a spot per line, the first at `caption`. Empty: the
  // caption is one line at `caption`.
  std::vector<std::string> caption_lines;
  std::vector<TextSpot> caption_spots;
  // The narration (Scene::narration), wrapped: its band across the bottom, and a spot per line.
  std::optional<Rect> narration_band;
  std::vector<std::string> narration_lines;
  std::vector<TextSpot> narration_spots;
  std::optional<LegendLayout> legend;
  Margins margins;  // what a camera fit should leave free
};

// `text` broken at blanks into lines of at most `columns` characters (a longer word alone on
// its line), at most `max_lines` of them, the last ending in "..." when the text goes on.
std::vector<std::string> wrap_words(std::string_view text, std::size_t columns, std::size_t max_lines);

// The layout of a scene's caption and legend (each only when present and visible) in a
// picture of width x height.
Layout layout(const Scene& scene, int width, int height);

// A camera that fits the scene's bounds into what its caption and legend leave free.
Camera fit_scene(const Scene& scene, int width, int height);

}  // namespace meshstep::scene
