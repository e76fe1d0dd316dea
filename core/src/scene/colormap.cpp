// The colour maps' stops and their interpolation.
#include "meshstep/scene/colormap.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace meshstep::scene {

namespace {

constexpr Rgba hex(std::uint32_t rgb) {
  return {static_cast<std::uint8_t>(rgb >> 16), static_cast<std::uint8_t>(rgb >> 8 & 0xFF),
          static_cast<std::uint8_t>(rgb & 0xFF), 255};
}

// Published colours of each map at evenly spaced positions (matplotlib's viridis, magma
// and cividis at tenths; magma from 0.2 up, its near-black start would swallow the edges).
// Between tenths the maps are close to straight lines in sRGB, so linear interpolation
// stays within a few units of the originals.
constexpr ColorStop kViridis[] = {
    {0.0, hex(0x440154)}, {0.1, hex(0x482475)}, {0.2, hex(0x414487)}, {0.3, hex(0x355F8D)},
    {0.4, hex(0x2A788E)}, {0.5, hex(0x21918C)}, {0.6, hex(0x22A884)}, {0.7, hex(0x44BF70)},
    {0.8, hex(0x7AD151)}, {0.9, hex(0xBDDF26)}, {1.0, hex(0xFDE725)}};

constexpr ColorStop kCividis[] = {
    {0.0, hex(0x00224E)}, {0.2, hex(0x35456C)}, {0.4, hex(0x666970)},
    {0.6, hex(0x948E77)}, {0.8, hex(0xC8B866)}, {1.0, hex(0xFEE838)}};

constexpr ColorStop kMagma[] = {
    {0.0, hex(0x3B0F70)}, {0.125, hex(0x641A80)}, {0.25, hex(0x8C2981)}, {0.375, hex(0xB73779)},
    {0.5, hex(0xDE4968)}, {0.625, hex(0xF7705C)}, {0.75, hex(0xFE9F6D)}, {0.875, hex(0xFECF92)},
    {1.0, hex(0xFCFDBF)}};

// The orange and blue halves of ColorBrewer's PuOr and Blues families (designed to be
// read by dichromats): darkest far from the bound.
constexpr ColorStop kOrangeBelow[] = {
    {0.0, hex(0x7F3B08)}, {0.35, hex(0xB35806)}, {0.7, hex(0xE08214)}, {1.0, hex(0xFDB863)}};

constexpr ColorStop kBlueAbove[] = {
    {0.0, hex(0xC6DBEF)}, {0.3, hex(0x9ECAE1)}, {0.65, hex(0x4292C6)}, {1.0, hex(0x084594)}};

constexpr std::array<Rgba, 8> kOkabeIto = {okabe::black, okabe::orange,    okabe::sky_blue,
                                           okabe::bluish_green, okabe::yellow, okabe::blue,
                                           okabe::vermillion, okabe::reddish_purple};

std::uint8_t channel(double x) { return static_cast<std::uint8_t>(std::clamp(std::lround(x), 0L, 255L)); }

}  // namespace

Rgba mix(Rgba a, Rgba b, double t) {
  const auto lerp = [t](std::uint8_t x, std::uint8_t y) { return channel(x + (double(y) - double(x)) * t); };
  return {lerp(a.r, b.r), lerp(a.g, b.g), lerp(a.b, b.b), lerp(a.a, b.a)};
}

ColorMap::ColorMap(std::span<const ColorStop> stops) : stops_(stops.begin(), stops.end()) {
  assert(!stops_.empty());
  assert(std::is_sorted(stops_.begin(), stops_.end(),
                        [](const ColorStop& x, const ColorStop& y) { return x.at < y.at; }));
}

Rgba ColorMap::operator()(double t) const {
  if (!(t > stops_.front().at)) return stops_.front().color;  // NaN too
  if (t >= stops_.back().at) return stops_.back().color;
  // The first stop beyond t; the one before it is at or below t.
  const auto hi = std::upper_bound(stops_.begin(), stops_.end(), t,
                                   [](double x, const ColorStop& s) { return x < s.at; });
  const auto lo = hi - 1;
  return mix(lo->color, hi->color, (t - lo->at) / (hi->at - lo->at));
}

std::vector<Rgba> ColorMap::samples(std::size_t n) const {
  std::vector<Rgba> out(std::max<std::size_t>(n, 2));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = (*this)(static_cast<double>(i) / (out.size() - 1));
  return out;
}

ColorTable::ColorTable(const ColorMap& map) {
  for (std::size_t i = 0; i < kSize; ++i) table_[i] = map(static_cast<double>(i) / (kSize - 1));
}

const ColorMap& viridis() {
  static const ColorMap map(kViridis);
  return map;
}
const ColorMap& cividis() {
  static const ColorMap map(kCividis);
  return map;
}
const ColorMap& magma() {
  static const ColorMap map(kMagma);
  return map;
}
const ColorMap& orange_below() {
  static const ColorMap map(kOrangeBelow);
  return map;
}
const ColorMap& blue_above() {
  static const ColorMap map(kBlueAbove);
  return map;
}

std::span<const Rgba, 8> okabe_ito() { return kOkabeIto; }

Rgba category_color(std::size_t i) {
  // Black is left out: it would read as a hole, and the edges and segments are dark.
  const Rgba base = kOkabeIto[1 + i % 7];
  switch (i / 7 % 3) {
    case 0: return base;
    case 1: return mix(base, {255, 255, 255, 255}, 0.55);
    default: return mix(base, {0, 0, 0, 255}, 0.45);
  }
}

}  // namespace meshstep::scene
