// Rectangles and glyphs in pixels, collected for one frame and drawn by UiPass: the caption's
// band and text, the legend, the labels. Every item samples a font atlas (plain rectangles
// its white patch), so items of one atlas draw together.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "font_atlas.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::render {

struct UiQuad {
  std::array<float, 4> rectangle;  // x0, y0, x1, y1: pixels, y down
  std::array<float, 4> texture;    // u0, v0, u1, v1
  scene::Rgba top, bottom;         // colour at the top and bottom edge (a vertical gradient)
};
static_assert(sizeof(UiQuad) == 40);

struct UiDraw {
  scene::Layer layer;
  GLuint texture;
  std::size_t first, count;
};

class UiBatch {
 public:
  // Drops the items, keeping the memory.
  void clear();
  // What the next items belong to: a layer (drawn at its turn) and the atlas they sample.
  void begin(scene::Layer layer, const FontAtlas& atlas);

  void rectangle(float x0, float y0, float x1, float y1, scene::Rgba color) { gradient(x0, y0, x1, y1, color, color); }
  void gradient(float x0, float y0, float x1, float y1, scene::Rgba top, scene::Rgba bottom);
  // UTF-8 text from the pen at (x, baseline), snapped to whole pixels; returns the pen's x
  // after it.
  float text(std::string_view utf8, float x, float baseline, scene::Rgba color);

  const std::vector<UiQuad>& quads() const { return quads_; }
  const std::vector<UiDraw>& draws() const { return draws_; }

 private:
  void add(const UiQuad& quad);
  std::vector<UiQuad> quads_;
  std::vector<UiDraw> draws_;
  const FontAtlas* atlas_ = nullptr;
  scene::Layer layer_ = scene::Layer::caption;
};

// The width in pixels of UTF-8 text set in an atlas (as UiBatch::text would advance).
float text_width(const FontAtlas& atlas, std::string_view utf8);

// The next code point of UTF-8 text from `at`, which moves past it; malformed bytes read as
// U+FFFD one byte at a time.
char32_t next_code_point(std::string_view utf8, std::size_t& at);

}  // namespace meshstep::render
