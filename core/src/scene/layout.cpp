#include "meshstep/scene/layout.hpp"

#include "meshstep/scene/label_placement.hpp"

#include <algorithm>
#include <cmath>

namespace meshstep::scene {
namespace {

// At text scale 1 (Scene::text_scale multiplies them).
constexpr double kCaptionBand = 30.0;     // px: a 16 px line with room above and below
constexpr double kCaptionFont = 16.0;
constexpr double kLegendFont = 13.0;
constexpr double kLegendWidth = 150.0;    // px kept free on the right for the legend
constexpr double kEdge = 12.0;            // px between the legend and the picture's border
constexpr double kCaptionShrink = 0.6;    // the smallest a long caption is set, of its size
constexpr double kCaptionWrapped = 0.75;  // a caption wrapped is set at this of its size
constexpr std::size_t kCaptionLines = 3;  // at most; the last ends in "..." when cut
constexpr double kCaptionLeading = 1.25;
constexpr double kEstimateSlack = 0.97;   // the width estimate may be a little short
// The narration is read from the back of a room: larger than the caption. DejaVu Sans's
// characters average about 0.5 of its size in running English (0.505 on the shipped
// tours); 0.53 keeps a line inside the picture without measuring glyphs here.
constexpr double kNarrationFont = 21.0;
constexpr double kNarrationCharWidth = 0.53;
constexpr double kNarrationLeading = 1.3;
constexpr std::size_t kNarrationLines = 4;

// `text` in lines no wider than `room` at `size` (estimated), broken at blanks; a middle dot
// stays with the word before it, so that no line begins with one. At most `max_lines`, the
// last ending in "..." when the text goes on.
std::vector<std::string> wrap_to_width(std::string_view text, double room, double size, std::size_t max_lines) {
  std::vector<std::string> words;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t begin = text.find_first_not_of(' ', at);
    if (begin == std::string_view::npos) break;
    const std::size_t end = std::min(text.find(' ', begin), text.size());
    const std::string_view word = text.substr(begin, end - begin);
    if (word == "\u00B7" && !words.empty()) words.back().append(" ").append(word);
    else words.emplace_back(word);
    at = end;
  }
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (lines.empty() || estimated_text_width(lines.back() + " " + words[i], size) > room) {
      if (lines.size() == max_lines) {
        lines.back() += " ...";
        break;
      }
      lines.push_back(words[i]);
    } else {
      lines.back().append(" ").append(words[i]);
    }
  }
  return lines;
}

// Sizes scaled by k (Scene::text_scale): the words grow, and the room kept for them.
LegendLayout legend_layout(const Legend& legend, int width, int height, double top, double k) {
  const double legend_width = kLegendWidth * k, font = kLegendFont * k;
  LegendLayout out;
  const double avail = height - top - 2 * kEdge;
  const double bar_h = std::clamp(0.45 * height, 80.0, std::max(80.0, avail - 40.0));
  const double bar_x = width - legend_width + kEdge;
  const double title = 28.0 * k;  // room above the bar for the title
  const double bar_y = top + kEdge + title + std::max(0.0, 0.5 * (avail - title - bar_h) * 0.25);
  out.panel = {width - legend_width + 2.0, bar_y - title - 2.0, legend_width - 2.0 - 4.0, bar_h + title + 12.0};
  out.title = {{static_cast<double>(width) - kEdge, bar_y - 12.0 * k}, font, true};
  if (legend.categorical) {
    const std::size_t n = std::max<std::size_t>(1, legend.colors.size());
    const double box = std::min(22.0, bar_h / static_cast<double>(n));
    for (std::size_t i = 0; i < legend.colors.size(); ++i)
      out.swatches.push_back({bar_x, bar_y + i * box, 16.0, box - 3.0});
    for (const Legend::Tick& t : legend.ticks) {
      // A categorical tick's `at` is the swatch's centre along the column, 0 at the top.
      const double y = bar_y + t.at * n * box;
      out.ticks.push_back({{bar_x + 16.0 + 8.0, y + 0.35 * font}, font, false});
      out.tick_y.push_back(y);
    }
    out.bar = {bar_x, bar_y, 16.0, n * box};
    return out;
  }
  out.bar = {bar_x, bar_y, 16.0, bar_h};
  for (const Legend::Tick& t : legend.ticks) {
    const double y = bar_y + (1.0 - t.at) * bar_h;  // the scale runs upward
    out.tick_y.push_back(y);
    out.ticks.push_back({{bar_x + 16.0 + out.tick_length + 4.0, y + 0.35 * font}, font, false});
  }
  return out;
}

}  // namespace

Layout layout(const Scene& scene, int width, int height) {
  Layout out;
  const double k = std::isfinite(scene.text_scale) ? std::clamp(static_cast<double>(scene.text_scale), 0.5, 4.0) : 1.0;
  const double band = kCaptionBand * k;
  if (scene.visible.has(Layer::caption) && !scene.caption.empty()) {
    out.caption_band = Rect{0.0, 0.0, static_cast<double>(width), band};
    // A caption wider than the picture (a long step at a large UI scale, a canvas narrowed
    // by the viewer's side panel) is set smaller, down to kCaptionShrink of its size, rather
    // than run on under the panel. Whole pixels: the renderer keeps one atlas per size.
    double size = kCaptionFont * k;
    const double room = width - 2.0 * 10.0 * k, wide = estimated_text_width(scene.caption, size);
    const double smallest = std::ceil(kCaptionShrink * size);
    if (wide > room && room > 0.0) size = std::max(std::floor(size * room / wide * kEstimateSlack), smallest);
    out.caption = {{10.0 * k, 0.5 * band + 0.35 * size}, size, false};
    out.margins.top = band + 16.0 * k;
    // Still too wide at the smallest size: in lines instead, each readable whole (cut at
    // the picture's edge, the end of a long step's words was lost).
    // A word wider than the picture by itself stays on one line, as small as it goes.
    const double wrapped_size = std::ceil(kCaptionWrapped * kCaptionFont * k);
    std::vector<std::string> lines;
    if (room > 0.0 && estimated_text_width(scene.caption, size) > room)
      lines = wrap_to_width(scene.caption, room * kEstimateSlack, wrapped_size, kCaptionLines);
    if (std::any_of(lines.begin(), lines.end(),
                    [&](const std::string& l) { return estimated_text_width(l, wrapped_size) > room; }))
      lines.clear();
    if (!lines.empty()) {
      size = wrapped_size;
      out.caption_lines = std::move(lines);
      const double line = kCaptionLeading * size, pad = 0.5 * (band - line);
      for (std::size_t i = 0; i < out.caption_lines.size(); ++i)
        out.caption_spots.push_back({{10.0 * k, pad + (static_cast<double>(i) + 0.5) * line + 0.35 * size}, size, false});
      out.caption = out.caption_spots.front();
      const double wrapped_band = 2.0 * pad + static_cast<double>(out.caption_lines.size()) * line;
      out.caption_band->h = wrapped_band;
      out.margins.top = wrapped_band + 16.0 * k;
    }
  }
  if (!scene.narration.empty()) {
    const double font = kNarrationFont * k, pad = 10.0 * k;
    const auto columns = static_cast<std::size_t>(std::max(10.0, (width - 2.0 * pad) / (kNarrationCharWidth * font)));
    out.narration_lines = wrap_words(scene.narration, columns, kNarrationLines);
    const double line = kNarrationLeading * font;
    const double band_h = static_cast<double>(out.narration_lines.size()) * line + 2.0 * pad - (line - font);
    out.narration_band = Rect{0.0, height - band_h, static_cast<double>(width), band_h};
    for (std::size_t i = 0; i < out.narration_lines.size(); ++i)
      out.narration_spots.push_back({{pad, height - band_h + pad + 0.8 * font + static_cast<double>(i) * line}, font, false});
    out.margins.bottom = band_h + 16.0 * k;
  }
  if (scene.visible.has(Layer::legend) && scene.legend)
    if (width > 3 * kLegendWidth * k) {  // a small picture has no room for a legend
      // Above the narration's band, when there is one.
      const int free_height = out.narration_band ? static_cast<int>(out.narration_band->y) : height;
      out.legend = legend_layout(*scene.legend, width, free_height, out.caption_band ? band : 0.0, k);
      out.margins.right = (kLegendWidth + 8.0) * k;
    }
  return out;
}

std::vector<std::string> wrap_words(std::string_view text, std::size_t columns, std::size_t max_lines) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t at = 0;
  bool cut = false;
  while (at < text.size()) {
    const std::size_t begin = text.find_first_not_of(" \t\n", at);
    if (begin == std::string_view::npos) break;
    const std::size_t end = std::min(text.find_first_of(" \t\n", begin), text.size());
    const std::string_view word = text.substr(begin, end - begin);
    at = end;
    // Columns count characters, not bytes: a UTF-8 continuation byte adds none.
    const auto chars = [](std::string_view s) {
      std::size_t n = 0;
      for (const char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
      return n;
    };
    if (!line.empty() && chars(line) + 1 + chars(word) > columns) {
      if (lines.size() + 1 == max_lines) {
        cut = true;
        break;
      }
      lines.push_back(std::move(line));
      line.clear();
    }
    line.append(line.empty() ? "" : " ").append(word);
  }
  if (!line.empty()) lines.push_back(cut ? line + "..." : line);
  return lines;
}

Camera fit_scene(const Scene& scene, int width, int height) {
  return Camera::fit(scene.bounds, width, height, layout(scene, width, height).margins);
}

}  // namespace meshstep::scene
