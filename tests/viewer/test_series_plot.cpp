// The plots' pictures (series_plot.hpp): each pixel column spans the values that fall in it,
// joined to the column before, on the scale given; NaN values leave gaps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "series_plot.hpp"

namespace meshstep::viewer {
namespace {

constexpr std::uint32_t kBack = 0xff000000u, kLine = 0xffffffffu;

std::uint32_t pixel(const scene::Image& image, int x, int y) {
  std::uint32_t c = 0;
  std::memcpy(&c, image.row(y) + static_cast<std::size_t>(x) * 4, 4);
  return c;
}

// The rows a column lights, top to bottom, as [first, last]; {-1, -1} for none.
std::pair<int, int> lit(const scene::Image& image, int x) {
  int first = -1, last = -1;
  for (int y = 0; y < image.height; ++y)
    if (pixel(image, x, y) == kLine) {
      if (first < 0) first = y;
      last = y;
    } else {
      EXPECT_EQ(pixel(image, x, y), kBack) << x << ", " << y;
    }
  return {first, last};
}

TEST(SeriesPlot, AConstantIsOneRowAndTheScaleSetsWhich) {
  scene::Image image;
  raster_series(std::vector<float>(50, 5.0f), 0.0f, 10.0f, 20, 11, kBack, kLine, image);
  ASSERT_EQ(image.width, 20);
  ASSERT_EQ(image.height, 11);
  for (int x = 0; x < 20; ++x) EXPECT_EQ(lit(image, x), std::make_pair(5, 5)) << x;  // half way up
  raster_series(std::vector<float>(50, 10.0f), 0.0f, 10.0f, 20, 11, kBack, kLine, image);
  EXPECT_EQ(lit(image, 7), std::make_pair(0, 0));  // the top row
  raster_series(std::vector<float>(50, -3.0f), 0.0f, 10.0f, 20, 11, kBack, kLine, image);
  EXPECT_EQ(lit(image, 7), std::make_pair(10, 10));  // below the scale: the bottom row
}

TEST(SeriesPlot, AColumnSpansItsValuesAndJoinsTheColumnBefore) {
  // Four values a column: 0, 10, 0, 10, then 2 in the next columns.
  std::vector<float> v = {0, 10, 0, 10, 2, 2, 2, 2, 2, 2, 2, 2};
  scene::Image image;
  raster_series(v, 0.0f, 10.0f, 3, 11, kBack, kLine, image);
  EXPECT_EQ(lit(image, 0), std::make_pair(0, 10));  // the whole span
  EXPECT_EQ(lit(image, 1), std::make_pair(0, 8));   // from 10 (the last before) down to 2
  EXPECT_EQ(lit(image, 2), std::make_pair(8, 8));
}

TEST(SeriesPlot, NanValuesLeaveAGapAndFewValuesWidenToTheColumns) {
  std::vector<float> v = {1, NAN, NAN, NAN, 1};
  scene::Image image;
  raster_series(v, 0.0f, 2.0f, 5, 3, kBack, kLine, image);
  EXPECT_EQ(lit(image, 0), std::make_pair(1, 1));
  EXPECT_EQ(lit(image, 1), std::make_pair(1, 1));  // the gap's first column still joins the value before
  raster_series({3.0f, 1.0f}, 0.0f, 4.0f, 4, 5, kBack, kLine, image);
  EXPECT_EQ(lit(image, 0), std::make_pair(1, 1));  // two values over four columns: two columns each
  EXPECT_EQ(lit(image, 1), std::make_pair(1, 1));
  EXPECT_EQ(lit(image, 2), std::make_pair(1, 3));
  EXPECT_EQ(lit(image, 3), std::make_pair(3, 3));
}

}  // namespace
}  // namespace meshstep::viewer
