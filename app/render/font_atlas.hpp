// Text glyphs baked into textures: the embedded DejaVu Sans, rasterised by stb_truetype at
// the exact pixel sizes the pictures use (caption 15 px, legend 13 px, labels their own),
// one atlas per size. Glyphs are placed on whole pixels and drawn texel for pixel, which is
// what keeps small text crisp.
#pragma once

#include <map>
#include <memory>
#include <string_view>
#include <vector>

#include "stb_truetype.hpp"

#include "gl_objects.hpp"

namespace meshstep::render {

// The font file, parsed once.
class Font {
 public:
  Font();  // the embedded DejaVuSans.ttf; throws std::runtime_error if it does not parse
  const stbtt_fontinfo& info() const { return info_; }
  const unsigned char* data() const { return data_; }

 private:
  const unsigned char* data_;
  stbtt_fontinfo info_;
};

struct Glyph {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // in the atlas, texels
  float x_offset = 0, y_offset = 0;    // of the box from the pen, pixels (y down)
  float advance = 0;
};

class FontAtlas {
 public:
  // Bakes the glyphs of the usual scripts and symbols (Latin, Greek, punctuation, arrows,
  // mathematical operators, geometric shapes) for an em of `size_px` pixels.
  FontAtlas(const Font& font, int size_px);

  int size_px() const { return size_px_; }
  float ascent() const { return ascent_; }      // above the baseline, pixels
  float descent() const { return descent_; }    // below the baseline, pixels (positive)
  float cap_height() const { return cap_height_; }
  // The glyph of a code point; '?' for one the atlas lacks.
  const Glyph& glyph(char32_t code_point) const;
  // The extra advance between two code points (negative: closer).
  float kerning(char32_t left, char32_t right) const;

  // Texture coordinates: atlas texels to 0..1.
  float u(float texel_x) const { return texel_x / static_cast<float>(width_); }
  float v(float texel_y) const { return texel_y / static_cast<float>(height_); }
  // A texel in a patch of full coverage, for plain rectangles drawn with the same texture.
  float white_u() const { return u(1.5f); }
  float white_v() const { return v(1.5f); }
  const Texture& texture() const { return texture_; }

 private:
  struct Range {
    char32_t first;
    int count;
    std::size_t glyph_index;  // of `first` in glyphs_
  };
  const Font& font_;
  int size_px_;
  float scale_;
  float ascent_ = 0, descent_ = 0, cap_height_ = 0;
  int width_ = 0, height_ = 0;
  std::vector<Range> ranges_;
  std::vector<Glyph> glyphs_;
  std::vector<bool> present_;
  std::size_t fallback_ = 0;
  Texture texture_;
};

// The atlases of the sizes in use, baked on first use. Sizes are whole pixels (6 to 96).
class FontCache {
 public:
  FontCache() = default;
  const FontAtlas& at(float size_px);
  // Call before each frame's text: forgets atlases the last frame did not use once more
  // than a few sizes are kept (a scene with labels of many sizes must not hoard textures).
  void begin_frame();

 private:
  struct Entry {
    std::unique_ptr<FontAtlas> atlas;
    unsigned long last_used = 0;
  };
  Font font_;
  std::map<int, Entry> atlases_;
  unsigned long frame_ = 0;
};

}  // namespace meshstep::render
