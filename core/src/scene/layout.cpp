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
constexpr double kEstimateSlack = 0.97;   // the width estimate may be a little short

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
    if (wide > room && room > 0.0)
      size = std::max(std::floor(size * room / wide * kEstimateSlack), std::ceil(kCaptionShrink * size));
    out.caption = {{10.0 * k, 0.5 * band + 0.35 * size}, size, false};
    out.margins.top = band + 16.0 * k;
  }
  if (scene.visible.has(Layer::legend) && scene.legend)
    if (width > 3 * kLegendWidth * k) {  // a small picture has no room for a legend
      out.legend = legend_layout(*scene.legend, width, height, out.caption_band ? band : 0.0, k);
      out.margins.right = (kLegendWidth + 8.0) * k;
    }
  return out;
}

Camera fit_scene(const Scene& scene, int width, int height) {
  return Camera::fit(scene.bounds, width, height, layout(scene, width, height).margins);
}

}  // namespace meshstep::scene
