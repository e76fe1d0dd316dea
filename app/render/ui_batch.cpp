#include "ui_batch.hpp"

#include <cmath>

namespace meshstep::render {

char32_t next_code_point(std::string_view s, std::size_t& at) {
  constexpr char32_t kReplacement = 0xfffd;
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned char lead = byte(at);
  int extra = 0;
  char32_t cp = 0;
  if (lead < 0x80) {
    ++at;
    return lead;
  } else if ((lead & 0xe0) == 0xc0) {
    extra = 1, cp = lead & 0x1f;
  } else if ((lead & 0xf0) == 0xe0) {
    extra = 2, cp = lead & 0x0f;
  } else if ((lead & 0xf8) == 0xf0) {
    extra = 3, cp = lead & 0x07;
  } else {
    ++at;
    return kReplacement;
  }
  if (at + static_cast<std::size_t>(extra) >= s.size()) {  // cut short
    ++at;
    return kReplacement;
  }
  for (int k = 1; k <= extra; ++k) {
    if ((byte(at + k) & 0xc0) != 0x80) {
      ++at;
      return kReplacement;
    }
    cp = cp << 6 | (byte(at + k) & 0x3f);
  }
  at += static_cast<std::size_t>(extra) + 1;
  return cp;
}

float text_width(const FontAtlas& atlas, std::string_view utf8) {
  float x = 0;
  char32_t previous = 0;
  for (std::size_t at = 0; at < utf8.size();) {
    const char32_t cp = next_code_point(utf8, at);
    if (previous) x += atlas.kerning(previous, cp);
    x += atlas.glyph(cp).advance;
    previous = cp;
  }
  return x;
}

void UiBatch::clear() {
  quads_.clear();
  draws_.clear();
  atlas_ = nullptr;
}

void UiBatch::begin(scene::Layer layer, const FontAtlas& atlas) {
  layer_ = layer;
  atlas_ = &atlas;
}

void UiBatch::add(const UiQuad& quad) {
  const GLuint texture = atlas_->texture().name();
  if (draws_.empty() || draws_.back().layer != layer_ || draws_.back().texture != texture)
    draws_.push_back({layer_, texture, quads_.size(), 0});
  quads_.push_back(quad);
  ++draws_.back().count;
}

void UiBatch::gradient(float x0, float y0, float x1, float y1, scene::Rgba top, scene::Rgba bottom) {
  const float u = atlas_->white_u(), v = atlas_->white_v();
  add({{x0, y0, x1, y1}, {u, v, u, v}, top, bottom});
}

float UiBatch::text(std::string_view utf8, float x, float baseline, scene::Rgba color) {
  const float y = std::round(baseline);
  char32_t previous = 0;
  for (std::size_t at = 0; at < utf8.size();) {
    const char32_t cp = next_code_point(utf8, at);
    if (previous) x += atlas_->kerning(previous, cp);
    const Glyph& g = atlas_->glyph(cp);
    if (g.x1 > g.x0) {
      // Whole pixels, one texel each: no resampling blur.
      const float left = std::round(x + g.x_offset), top = std::round(y + g.y_offset);
      const float w = static_cast<float>(g.x1 - g.x0), h = static_cast<float>(g.y1 - g.y0);
      add({{left, top, left + w, top + h},
           {atlas_->u(static_cast<float>(g.x0)), atlas_->v(static_cast<float>(g.y0)),
            atlas_->u(static_cast<float>(g.x1)), atlas_->v(static_cast<float>(g.y1))},
           color,
           color});
    }
    x += g.advance;
    previous = cp;
  }
  return x;
}

}  // namespace meshstep::render
