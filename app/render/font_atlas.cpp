#include "font_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "embedded_files.hpp"

namespace meshstep::render {

namespace {

// The code points baked: what captions, legends and labels may say.
struct CodePointRange {
  char32_t first, last;
};
constexpr CodePointRange kBakedRanges[] = {
    {0x0020, 0x007e},  // ASCII
    {0x00a0, 0x017f},  // Latin-1 and Latin Extended-A (° · × ± ², accented names)
    {0x0391, 0x03c9},  // Greek (θ α Δ ...)
    {0x2010, 0x2027},  // dashes, quotes, bullet, ellipsis
    {0x2030, 0x203a},  // per mille, primes
    {0x2070, 0x209c},  // superscripts and subscripts
    {0x2190, 0x21ff},  // arrows
    {0x2200, 0x22ff},  // mathematical operators (≤ ≥ ≈ ∞ −)
    {0x25a0, 0x25ff},  // geometric shapes (■ ● ▲)
};

// Rows kept free at the top of every atlas, the first few texels of which are a white patch.
constexpr int kReservedRows = 4;

}  // namespace

Font::Font() {
  const std::string_view file = embedded_file("DejaVuSans.ttf");
  data_ = reinterpret_cast<const unsigned char*>(file.data());
  if (!stbtt_InitFont(&info_, data_, stbtt_GetFontOffsetForIndex(data_, 0)))
    throw std::runtime_error("the embedded font DejaVuSans.ttf does not parse");
}

FontAtlas::FontAtlas(const Font& font, int size_px)
    : font_(font), size_px_(size_px), scale_(stbtt_ScaleForMappingEmToPixels(&font.info(), static_cast<float>(size_px))) {
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&font.info(), &ascent, &descent, &gap);
  ascent_ = ascent * scale_;
  descent_ = -descent * scale_;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  cap_height_ = stbtt_GetCodepointBox(&font.info(), 'H', &x0, &y0, &x1, &y1) ? y1 * scale_ : 0.7f * size_px;

  std::size_t total = 0;
  for (const CodePointRange& r : kBakedRanges) {
    const int count = static_cast<int>(r.last - r.first + 1);
    ranges_.push_back({r.first, count, total});
    total += static_cast<std::size_t>(count);
  }
  std::vector<stbtt_packedchar> packed(total);
  std::vector<stbtt_pack_range> pack_ranges;
  for (const Range& r : ranges_) {
    stbtt_pack_range p{};
    p.font_size = STBTT_POINT_SIZE(static_cast<float>(size_px));  // the em, as CSS and SVG sizes
    p.first_unicode_codepoint_in_range = static_cast<int>(r.first);
    p.num_chars = r.count;
    p.chardata_for_range = packed.data() + r.glyph_index;
    pack_ranges.push_back(p);
  }

  // Pack into a 512-wide atlas, doubling its height until everything fits.
  width_ = 512;
  std::vector<unsigned char> pixels;
  for (int rows = 128;; rows *= 2) {
    if (rows > 8192) throw std::runtime_error("font atlas too large for " + std::to_string(size_px) + " px");
    height_ = rows + kReservedRows;
    pixels.assign(static_cast<std::size_t>(width_) * height_, 0);
    stbtt_pack_context context;
    if (!stbtt_PackBegin(&context, pixels.data() + kReservedRows * width_, width_, rows, width_, 1, nullptr))
      throw std::runtime_error("font atlas: out of memory");
    // Missing code points share the font's "missing" glyph (present_ tells them apart).
    const int all_fit = stbtt_PackFontRanges(&context, font.data(), 0, pack_ranges.data(),
                                             static_cast<int>(pack_ranges.size()));
    stbtt_PackEnd(&context);
    if (all_fit) break;
  }
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) pixels[static_cast<std::size_t>(y) * width_ + x] = 255;

  glyphs_.resize(total);
  present_.resize(total);
  for (const Range& r : ranges_)
    for (int i = 0; i < r.count; ++i) {
      const stbtt_packedchar& p = packed[r.glyph_index + i];
      Glyph& g = glyphs_[r.glyph_index + i];
      g = {p.x0, p.y0 + kReservedRows, p.x1, p.y1 + kReservedRows, p.xoff, p.yoff, p.xadvance};
      present_[r.glyph_index + i] = stbtt_FindGlyphIndex(&font.info(), static_cast<int>(r.first) + i) != 0;
    }
  fallback_ = ranges_[0].glyph_index + ('?' - ranges_[0].first);

  texture_.bind();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, width_, height_, 0, GL_RED, GL_UNSIGNED_BYTE, pixels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

const Glyph& FontAtlas::glyph(char32_t code_point) const {
  for (const Range& r : ranges_)
    if (code_point >= r.first && code_point < r.first + static_cast<char32_t>(r.count)) {
      const std::size_t i = r.glyph_index + (code_point - r.first);
      return present_[i] ? glyphs_[i] : glyphs_[fallback_];
    }
  return glyphs_[fallback_];
}

float FontAtlas::kerning(char32_t left, char32_t right) const {
  return scale_ * static_cast<float>(stbtt_GetCodepointKernAdvance(&font_.info(), static_cast<int>(left),
                                                                    static_cast<int>(right)));
}

const FontAtlas& FontCache::at(float size_px) {
  const float wanted = std::isfinite(size_px) ? std::clamp(size_px, 6.0f, 96.0f) : 14.0f;
  const int size = static_cast<int>(std::lround(wanted));
  Entry& entry = atlases_[size];
  if (!entry.atlas) entry.atlas = std::make_unique<FontAtlas>(font_, size);
  entry.last_used = frame_;
  return *entry.atlas;
}

void FontCache::begin_frame() {
  constexpr std::size_t kKeptSizes = 6;
  if (atlases_.size() > kKeptSizes)
    std::erase_if(atlases_, [this](const auto& item) { return item.second.last_used < frame_; });
  ++frame_;
}

}  // namespace meshstep::render
