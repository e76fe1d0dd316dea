// The colour maps and the names of layers and fills: the maps must rise in lightness (so
// they read in greyscale and for colour-blind readers), the diverging map must put every
// value below the bound on the orange side and every other on the blue side, the category
// colours must differ, and every name must parse back.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

#include "meshstep/scene/colormap.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene {
namespace {

// WCAG relative luminance of an sRGB colour.
double luminance(Rgba c) {
  const auto linear = [](std::uint8_t v) {
    const double s = v / 255.0;
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
}

TEST(SceneColorMap, EndsAreTheFirstAndLastStops) {
  for (const ColorMap* m : {&viridis(), &cividis(), &magma(), &orange_below(), &blue_above()}) {
    EXPECT_EQ((*m)(0.0), m->stops().front().color);
    EXPECT_EQ((*m)(1.0), m->stops().back().color);
    EXPECT_EQ((*m)(-3.0), m->stops().front().color) << "clamped below";
    EXPECT_EQ((*m)(7.0), m->stops().back().color) << "clamped above";
    EXPECT_EQ((*m)(NAN), m->stops().front().color);
    for (const ColorStop& s : m->stops()) EXPECT_EQ((*m)(s.at), s.color) << "a stop is hit exactly";
  }
}

TEST(SceneColorMap, InterpolatesLinearlyBetweenStops) {
  const ColorStop stops[] = {{0.0, {0, 100, 200, 255}}, {0.5, {100, 100, 0, 255}}, {1.0, {200, 0, 0, 255}}};
  const ColorMap m(stops);
  EXPECT_EQ(m(0.25), (Rgba{50, 100, 100, 255}));
  EXPECT_EQ(m(0.75), (Rgba{150, 50, 0, 255}));
  const std::vector<Rgba> s = m.samples(5);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_EQ(s[1], m(0.25));
  EXPECT_EQ(s[4], m(1.0));
}

// Sequential maps read as "more" in greyscale: lightness rises all along them.
TEST(SceneColorMap, SequentialMapsRiseInLightness) {
  for (const ColorMap* m : {&viridis(), &cividis(), &magma()}) {
    const std::vector<Rgba> s = m->samples(256);
    for (std::size_t i = 1; i < s.size(); ++i) EXPECT_GT(luminance(s[i]), luminance(s[i - 1]) - 1e-4) << "sample " << i;
    EXPECT_GT(luminance(s.back()) - luminance(s.front()), 0.5);
  }
}

// Below the bound orange (red over blue), from the bound up blue (blue over red), darker away
// from the bound on both sides, and a visible jump between the two.
TEST(SceneColorMap, DivergingHalvesAreOrangeBelowAndBlueAbove) {
  for (const Rgba c : orange_below().samples(64)) EXPECT_GT(int(c.r), int(c.b) + 60);
  for (const Rgba c : blue_above().samples(64)) EXPECT_GT(int(c.b), int(c.r) + 20);
  const std::vector<Rgba> below = orange_below().samples(64), above = blue_above().samples(64);
  for (std::size_t i = 1; i < below.size(); ++i) EXPECT_GE(luminance(below[i]), luminance(below[i - 1]) - 1e-4);
  for (std::size_t i = 1; i < above.size(); ++i) EXPECT_LE(luminance(above[i]), luminance(above[i - 1]) + 1e-4);
}

TEST(SceneColorMap, TableAgreesWithTheMap) {
  const ColorTable table(viridis());
  for (int i = 0; i <= 1000; ++i) {
    const double t = i / 1000.0;
    const Rgba a = table(t), b = viridis()(t);
    EXPECT_LE(std::abs(int(a.r) - int(b.r)), 1);
    EXPECT_LE(std::abs(int(a.g) - int(b.g)), 1);
    EXPECT_LE(std::abs(int(a.b) - int(b.b)), 1);
  }
  EXPECT_EQ(table(NAN), viridis()(0.0));
  EXPECT_EQ(table(2.0), viridis()(1.0));
}

TEST(SceneColorMap, OkabeItoAndCategoriesAreDistinct) {
  const auto palette = okabe_ito();
  EXPECT_EQ(palette[0], (Rgba{0, 0, 0, 255}));
  EXPECT_EQ(palette[1], (Rgba{230, 159, 0, 255}));
  EXPECT_EQ(palette[6], (Rgba{213, 94, 0, 255}));
  std::set<std::tuple<int, int, int>> seen;
  for (std::size_t i = 0; i < 21; ++i) {
    const Rgba c = category_color(i);
    EXPECT_EQ(c.a, 255);
    EXPECT_TRUE(seen.insert({c.r, c.g, c.b}).second) << "category " << i << " repeats a colour";
  }
  EXPECT_EQ(category_color(21), category_color(0)) << "round again after 21";
}

TEST(SceneColorMap, MixAndAlpha) {
  EXPECT_EQ(mix({0, 0, 0, 0}, {255, 255, 255, 255}, 0.5), (Rgba{128, 128, 128, 128}));
  EXPECT_EQ(with_alpha({1, 2, 3, 255}, 7), (Rgba{1, 2, 3, 7}));
}

TEST(SceneNames, LayersAndFillsParseBack) {
  for (std::size_t i = 0; i < kLayerCount; ++i) {
    const auto l = static_cast<Layer>(i);
    ASSERT_TRUE(parse_layer(name(l)).has_value()) << name(l);
    EXPECT_EQ(*parse_layer(name(l)), l);
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(ColorBy::count_); ++i) {
    const auto c = static_cast<ColorBy>(i);
    ASSERT_TRUE(parse_color_by(name(c)).has_value()) << name(c);
    EXPECT_EQ(*parse_color_by(name(c)), c);
  }
  EXPECT_FALSE(parse_layer("overlays").has_value());
  EXPECT_FALSE(parse_layer("").has_value());
  EXPECT_FALSE(parse_color_by("Angle").has_value());
  EXPECT_EQ(std::string(name(Layer::overlay)), "overlay");
  EXPECT_EQ(std::string(name(ColorBy::quality)), "quality");
}

}  // namespace
}  // namespace meshstep::scene
