// The themes' colours (see style.hpp for what each hue means).
#include "style.hpp"

namespace meshstep::scene::detail {

namespace {

using namespace okabe;

constexpr Rgba kClear{0, 0, 0, 0};  // no fill
constexpr Rgba kWhite{255, 255, 255, 255};
constexpr Rgba kInk{20, 20, 20, 255};      // the light theme's "black": text, segments
// Okabe-Ito orange darkened for strokes on white (the orange itself has a contrast of 2.2).
constexpr Rgba kOrangeOnLight{184, 112, 0, 255};
constexpr Rgba kPaper{236, 236, 236, 255}; // the dark theme's "white"

// Lighter variants of the dark hues for the dark theme.
constexpr Rgba kBlueOnDark{86, 180, 233, 255};        // Okabe-Ito sky blue
constexpr Rgba kSkyOnDark{160, 212, 242, 255};
constexpr Rgba kVermillionOnDark{242, 124, 44, 255};
constexpr Rgba kGreenOnDark{36, 190, 142, 255};
constexpr Rgba kPurpleOnDark{222, 146, 190, 255};

constexpr BaseStyle kLightBase{
    .background = kWhite,
    .neutral_fill = {232, 234, 237, 255},
    .edge = {0, 0, 0, 70},
    .edge_width_px = 1.0f,
    .segment = kInk,
    .segment_width_px = 2.5f,
    .input_vertex = kInk,
    .steiner_vertex = blue,
    .vertex_outline = kWhite,
    .hole = kInk,
    .region_point = bluish_green,
    .text = kInk,
    .voronoi = vermillion,
    .voronoi_width_px = 2.0f,
    .voronoi_site = kInk,
    .faint_edge = {0, 0, 0, 38},
};

constexpr BaseStyle kDarkBase{
    .background = {20, 22, 26, 255},
    .neutral_fill = {52, 57, 66, 255},
    .edge = {255, 255, 255, 60},
    .edge_width_px = 1.0f,
    .segment = kPaper,
    .segment_width_px = 2.5f,
    .input_vertex = kPaper,
    .steiner_vertex = kBlueOnDark,
    .vertex_outline = {20, 22, 26, 255},
    .hole = kPaper,
    .region_point = kGreenOnDark,
    .text = kPaper,
    .voronoi = kVermillionOnDark,
    .voronoi_width_px = 2.0f,
    .voronoi_site = kPaper,
    .faint_edge = {255, 255, 255, 40},
};

// A projector washes out grey and thin lines: opaque black edges at twice the width, and
// segments and vertices that stay visible from the back of a room.
constexpr BaseStyle kHighContrastBase{
    .background = kWhite,
    .neutral_fill = kWhite,
    .edge = {0, 0, 0, 255},
    .edge_width_px = 2.0f,
    .segment = {0, 0, 0, 255},
    .segment_width_px = 4.5f,
    .input_vertex = {0, 0, 0, 255},
    .steiner_vertex = blue,
    .vertex_outline = kWhite,
    .hole = {0, 0, 0, 255},
    .region_point = bluish_green,
    .text = {0, 0, 0, 255},
    .voronoi = vermillion,
    .voronoi_width_px = 3.5f,
    .voronoi_site = {0, 0, 0, 255},
    .faint_edge = {0, 0, 0, 110},
};

// Translucent fills: strong enough to tint any colour map, weak enough to read it through.
constexpr std::uint8_t kFill = 80, kLightFill = 50, kStrongFill = 110;

constexpr OverlayStyle kLightOverlay{
    .located = {blue, with_alpha(sky_blue, kFill)},
    .walk = {blue, with_alpha(sky_blue, kLightFill)},
    .bad = {vermillion, with_alpha(vermillion, kFill)},
    .circumcircle = {vermillion, kClear},
    .selected = {kInk, yellow},
    .alternative = {reddish_purple, kClear},
    .lepp = {bluish_green, with_alpha(bluish_green, kFill)},
    .terminal_triangles = {kOrangeOnLight, with_alpha(orange, kStrongFill)},
    .terminal_edge = {reddish_purple, kClear},
    .cavity = {kOrangeOnLight, with_alpha(orange, kFill)},
    .new_fan = {bluish_green, with_alpha(bluish_green, kLightFill)},
    .cavity_boundary = {blue, kClear},
    .flip_before = {reddish_purple, kClear},
    .flip_after = {blue, kClear},
    .flip_circle = {bluish_green, kClear},
    .encroached = {vermillion, kClear},
    .diametral = {vermillion, kClear},
    .encroacher = {kInk, reddish_purple},
    .split = {kInk, yellow},
    .bisected = {vermillion, kClear},
    .bisection_new = {blue, kClear},
    .recovered = {vermillion, kClear},
    .removed = {vermillion, kClear},
    .star = {kOrangeOnLight, with_alpha(orange, kFill)},
    .failed = {vermillion, with_alpha(vermillion, kStrongFill)},
    .changed = {yellow, with_alpha(yellow, 120)},
    .marker_outline = kInk,
    .label = kInk,
    .faded_alpha = 110,
};

constexpr OverlayStyle kDarkOverlay{
    .located = {kBlueOnDark, with_alpha(kSkyOnDark, kFill)},
    .walk = {kBlueOnDark, with_alpha(kSkyOnDark, kLightFill)},
    .bad = {kVermillionOnDark, with_alpha(kVermillionOnDark, kFill)},
    .circumcircle = {kVermillionOnDark, kClear},
    .selected = {kInk, yellow},
    .alternative = {kPurpleOnDark, kClear},
    .lepp = {kGreenOnDark, with_alpha(kGreenOnDark, kFill)},
    .terminal_triangles = {orange, with_alpha(orange, kStrongFill)},
    .terminal_edge = {kPurpleOnDark, kClear},
    .cavity = {orange, with_alpha(orange, kFill)},
    .new_fan = {kGreenOnDark, with_alpha(kGreenOnDark, kLightFill)},
    .cavity_boundary = {kBlueOnDark, kClear},
    .flip_before = {kPurpleOnDark, kClear},
    .flip_after = {kBlueOnDark, kClear},
    .flip_circle = {kGreenOnDark, kClear},
    .encroached = {kVermillionOnDark, kClear},
    .diametral = {kVermillionOnDark, kClear},
    .encroacher = {kInk, kPurpleOnDark},
    .split = {kInk, yellow},
    .bisected = {kVermillionOnDark, kClear},
    .bisection_new = {kBlueOnDark, kClear},
    .recovered = {kVermillionOnDark, kClear},
    .removed = {kVermillionOnDark, kClear},
    .star = {orange, with_alpha(orange, kFill)},
    .failed = {kVermillionOnDark, with_alpha(kVermillionOnDark, kStrongFill)},
    .changed = {yellow, with_alpha(yellow, 90)},
    .marker_outline = kInk,
    .label = kPaper,
    .faded_alpha = 120,
};

}  // namespace

const BaseStyle& base_style(Theme theme) {
  switch (theme) {
    case Theme::dark: return kDarkBase;
    case Theme::high_contrast: return kHighContrastBase;
    case Theme::light: break;
  }
  return kLightBase;
}
// The light theme's overlay colours are the strong ones on white already.
const OverlayStyle& overlay_style(Theme theme) { return theme == Theme::dark ? kDarkOverlay : kLightOverlay; }

}  // namespace meshstep::scene::detail
