// Colour maps for filling triangles by a quantity, and the palette for categories.
//
// Every map here is safe for the common colour-vision deficiencies and reads in greyscale:
// the sequential maps rise monotonically in lightness (viridis, cividis and magma, by their
// published colours at a few positions, interpolated linearly in between), the diverging map
// is orange against blue, and categories take the Okabe-Ito palette.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "meshstep/scene/scene.hpp"

namespace meshstep::scene {

struct ColorStop {
  double at = 0.0;  // 0..1, increasing along a map
  Rgba color;
};

// A piecewise-linear map from [0, 1] to colours, through its stops. Positions outside [0, 1]
// are clamped; NaN maps to the first colour.
class ColorMap {
 public:
  explicit ColorMap(std::span<const ColorStop> stops);  // at least one stop
  Rgba operator()(double t) const;
  // n colours evenly spaced from 0 to 1 (n >= 2): a legend's bar.
  std::vector<Rgba> samples(std::size_t n) const;
  std::span<const ColorStop> stops() const { return stops_; }

 private:
  std::vector<ColorStop> stops_;
};

// A map sampled once into a table, for colouring a million triangles without searching stops.
// Lookups round to the nearest of kSize entries (error under 1/2000 of the range).
class ColorTable {
 public:
  static constexpr std::size_t kSize = 1024;
  explicit ColorTable(const ColorMap& map);
  Rgba operator()(double t) const {
    // NaN fails both comparisons and lands on entry 0, as ColorMap does.
    const double x = t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
    return table_[static_cast<std::size_t>(x * (kSize - 1) + 0.5)];
  }

 private:
  std::array<Rgba, kSize> table_;
};

// Sequential maps, dark to light.
const ColorMap& viridis();  // purple, blue, green, yellow: the smallest angle
const ColorMap& cividis();  // navy, grey, yellow (the same for every colour vision): area
const ColorMap& magma();    // purple, pink, pale yellow, without magma's black end: age

// The two halves of the diverging blue/orange map that quality is drawn with. They meet
// with a jump, not at a common white: a triangle just below a bound is plainly orange and
// one just above plainly pale blue.
const ColorMap& orange_below();  // 0: deep burnt orange (far below), 1: light orange (just below)
const ColorMap& blue_above();     // 0: pale blue (just above), 1: deep blue (far above)

// Okabe & Ito (2008), "Color Universal Design": eight colours distinguishable under
// protanopia, deuteranopia and tritanopia. In their order: black, orange, sky blue, bluish
// green, yellow, blue, vermillion, reddish purple.
std::span<const Rgba, 8> okabe_ito();
namespace okabe {
inline constexpr Rgba black{0, 0, 0, 255};
inline constexpr Rgba orange{230, 159, 0, 255};
inline constexpr Rgba sky_blue{86, 180, 233, 255};
inline constexpr Rgba bluish_green{0, 158, 115, 255};
inline constexpr Rgba yellow{240, 228, 66, 255};
inline constexpr Rgba blue{0, 114, 178, 255};
inline constexpr Rgba vermillion{213, 94, 0, 255};
inline constexpr Rgba reddish_purple{204, 121, 167, 255};
}  // namespace okabe

// The colour of category i for filling areas: the Okabe-Ito colours without black, then
// the same seven lightened, then darkened (21 distinct colours), then round again.
Rgba category_color(std::size_t i);

// a + (b - a) t per channel, alpha included (t in [0, 1]).
Rgba mix(Rgba a, Rgba b, double t);
inline constexpr Rgba with_alpha(Rgba c, std::uint8_t a) {
  c.a = a;
  return c;
}

}  // namespace meshstep::scene
