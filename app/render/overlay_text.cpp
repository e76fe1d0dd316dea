#include "overlay_text.hpp"

#include "meshstep/scene/label_placement.hpp"

#include <algorithm>
#include <cmath>

namespace meshstep::render {

namespace {

using scene::Rect;
using scene::Rgba;

Rgba with_alpha(Rgba c, std::uint8_t a) {
  c.a = a;
  return c;
}

// The scene's text colour, or the theme's when the scene leaves it transparent.
Rgba text_color(const scene::Scene& s) {
  if (s.caption_color.a > 0) return s.caption_color;
  return s.theme == scene::Theme::dark ? Rgba{235, 235, 235, 255} : Rgba{25, 25, 25, 255};
}

// What text sits on: the background, mostly opaque, so that it reads over the mesh.
Rgba panel_color(const scene::Scene& s, std::uint8_t alpha) {
  if (s.background.a > 0) return with_alpha(s.background, alpha);
  return s.theme == scene::Theme::dark ? Rgba{30, 30, 30, alpha} : Rgba{255, 255, 255, alpha};
}

float f(double v) { return static_cast<float>(v); }

void rectangle(UiBatch& batch, const Rect& r, Rgba color, float grow = 0.0f) {
  batch.rectangle(f(r.x) - grow, f(r.y) - grow, f(r.x + r.w) + grow, f(r.y + r.h) + grow, color);
}

// Text at a layout's spot: starting there, or ending there when anchored at its end.
void text_at(UiBatch& batch, FontCache& fonts, const scene::TextSpot& spot, std::string_view text, Rgba color,
             scene::Layer layer) {
  const FontAtlas& font = fonts.at(f(spot.size_px));
  batch.begin(layer, font);
  const float x = f(spot.at.x) - (spot.anchor_end ? text_width(font, text) : 0.0f);
  batch.text(text, std::round(x), f(spot.at.y), color);
}

}  // namespace

void add_caption(const scene::Scene& s, const scene::Layout& layout, FontCache& fonts, UiBatch& batch) {
  if (!layout.caption_band || s.caption.empty()) return;
  batch.begin(scene::Layer::caption, fonts.at(f(layout.caption.size_px)));
  rectangle(batch, *layout.caption_band, panel_color(s, 200));
  if (layout.caption_lines.empty()) {
    text_at(batch, fonts, layout.caption, s.caption, text_color(s), scene::Layer::caption);
    return;
  }
  for (std::size_t i = 0; i < layout.caption_lines.size(); ++i)
    text_at(batch, fonts, layout.caption_spots[i], layout.caption_lines[i], text_color(s), scene::Layer::caption);
}

void add_narration(const scene::Scene& s, const scene::Layout& layout, FontCache& fonts, UiBatch& batch) {
  if (!layout.narration_band || layout.narration_spots.empty()) return;
  batch.begin(kNoteLayer, fonts.at(f(layout.narration_spots[0].size_px)));
  // Nearly opaque: sentences are read, not glanced at, and the mesh is above the band.
  const Rect& band = *layout.narration_band;
  rectangle(batch, band, panel_color(s, 235));
  // A hairline along its top: the band is part of the picture, not of the mesh.
  batch.rectangle(f(band.x), f(band.y), f(band.x + band.w), f(band.y) + 1.0f, with_alpha(text_color(s), 70));
  for (std::size_t i = 0; i < layout.narration_spots.size() && i < layout.narration_lines.size(); ++i)
    text_at(batch, fonts, layout.narration_spots[i], layout.narration_lines[i], text_color(s), kNoteLayer);
}

void add_legend(const scene::Scene& s, const scene::Layout& layout, FontCache& fonts, UiBatch& batch) {
  if (!layout.legend || !s.legend) return;
  const scene::LegendLayout& place = *layout.legend;
  const scene::Legend& legend = *s.legend;
  const Rgba ink = text_color(s);
  constexpr auto kLayer = scene::Layer::legend;
  batch.begin(kLayer, fonts.at(f(place.title.size_px)));
  rectangle(batch, place.panel, with_alpha(ink, 40), 1.0f);  // a hairline frame
  rectangle(batch, place.panel, panel_color(s, 225));

  const std::size_t n = legend.colors.size();
  if (legend.categorical) {
    for (std::size_t i = 0; i < place.swatches.size() && i < n; ++i) rectangle(batch, place.swatches[i], legend.colors[i]);
  } else if (n > 0) {
    const Rect& bar = place.bar;
    rectangle(batch, bar, with_alpha(ink, 90), 1.0f);
    if (n == 1) rectangle(batch, bar, legend.colors[0]);
    // Evenly spaced stops, the first at the bottom; the GPU interpolates between neighbours.
    const double bottom = bar.y + bar.h;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const double below = bottom - bar.h * static_cast<double>(i) / static_cast<double>(n - 1);
      const double above = bottom - bar.h * static_cast<double>(i + 1) / static_cast<double>(n - 1);
      batch.gradient(f(bar.x), f(above), f(bar.x + bar.w), f(below), legend.colors[i + 1], legend.colors[i]);
    }
    // Tick marks from the bar's right side, one pixel thick (an emphasized one two), ending
    // at their y.
    for (std::size_t i = 0; i < place.tick_y.size(); ++i) {
      const bool strong = i < legend.ticks.size() && legend.ticks[i].emphasized;
      const float y = f(place.tick_y[i]), x = f(bar.x + bar.w);
      batch.rectangle(x, y - (strong ? 2.0f : 1.0f), x + f(place.tick_length), y, ink);
    }
  }
  for (std::size_t i = 0; i < place.ticks.size() && i < legend.ticks.size(); ++i)
    text_at(batch, fonts, place.ticks[i], legend.ticks[i].text, ink, kLayer);
  if (!legend.title.empty()) text_at(batch, fonts, place.title, legend.title, ink, kLayer);
}

void add_labels(const scene::Scene& s, const scene::Camera& camera, FontCache& fonts, UiBatch& batch) {
  const Rgba halo = panel_color(s, 160);
  // Placed so that no two overlap and none covers a vertex (scene/label_placement.hpp),
  // measured with the fonts that draw them.
  const scene::MeasureText measure = [&](std::string_view text, double size_px) {
    const FontAtlas& font = fonts.at(static_cast<float>(size_px));
    return scene::TextExtent{text_width(font, text), std::ceil(font.ascent()), std::ceil(font.descent())};
  };
  for (const scene::PlacedLabel& p : scene::place_labels(s, camera, measure)) {
    const scene::Label& label = s.labels[p.label];
    const FontAtlas& font = fonts.at(static_cast<float>(p.size_px));
    batch.begin(scene::Layer::labels, font);
    // A translucent box behind the text, so that it reads over the mesh.
    batch.rectangle(f(p.x0), f(p.y0), f(p.x1), f(p.y1), halo);
    batch.text(label.text, f(p.left), f(p.baseline), label.color);
  }
}

void add_note(const scene::Scene& s, int height, std::string_view note, FontCache& fonts, UiBatch& batch) {
  if (note.empty()) return;
  constexpr float kSize = 13.0f, kMargin = 6.0f, kPad = 4.0f;
  const FontAtlas& font = fonts.at(kSize);
  batch.begin(kNoteLayer, font);
  const float base = std::round(static_cast<float>(height) - kMargin - kPad - std::ceil(font.descent()));
  const float left = kMargin + kPad, right = left + text_width(font, note);
  batch.rectangle(kMargin, base - std::ceil(font.ascent()) - kPad, right + kPad, base + std::ceil(font.descent()) + kPad,
                  panel_color(s, 215));
  batch.text(note, left, base, text_color(s));
}

}  // namespace meshstep::render
