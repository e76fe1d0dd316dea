// The SVG plot writer: a logarithmic axis puts decades at equal distances and labels them
// 1, 10, 100, 1000, 10⁴...; the left margin grows with the widest tick label, so that the
// axis title never runs into the numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "svg_plot.hpp"

namespace {

using meshstep::app::PlotPanel;
using meshstep::app::PlotSeries;

// The y coordinates of the first series' line ("M x y L x y ...").
std::vector<double> line_ys(const std::string& svg) {
  const std::size_t d = svg.find(" d=\"M", svg.find("class=\"series\""));
  std::vector<double> ys;
  const char* p = svg.c_str() + d + 5;
  while (true) {
    char* end = nullptr;
    std::strtod(p, &end);  // x
    ys.push_back(std::strtod(end, &end));
    if (*end != 'L') break;
    p = end + 1;
  }
  return ys;
}

// The x of the frame (the plot area's left edge).
double frame_left(const std::string& svg) {
  const std::size_t at = svg.rfind("<rect x=\"", svg.find("fill=\"none\" stroke=\"#222\""));
  return std::strtod(svg.c_str() + at + 9, nullptr);
}

PlotPanel counts(bool log) {
  PlotPanel p;
  p.title = "Steiner points";
  p.x_label = "bound";
  p.y_label = "Steiner points";
  p.y_log = log;
  p.series.push_back(PlotSeries{"runaway", {{20, 10}, {22, 100}, {24, 1000}, {26, 100000}}, true});
  return p;
}

TEST(SvgPlot, ALogAxisSpacesDecadesEquallyAndLabelsThem) {
  const std::string svg = meshstep::app::svg_figure({counts(true)});
  const std::vector<double> y = line_ys(svg);
  ASSERT_EQ(y.size(), 4u);
  const double decade = y[0] - y[1];
  EXPECT_GT(decade, 10.0);
  EXPECT_NEAR(y[1] - y[2], decade, 0.02);
  EXPECT_NEAR(y[2] - y[3], 2 * decade, 0.02);
  for (const char* label : {">10<", ">100<", ">1000<", ">10\u2074<", ">10\u2075<"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;

  // On a linear axis the same data is not evenly spaced: the test above can fail.
  const std::vector<double> linear = line_ys(meshstep::app::svg_figure({counts(false)}));
  EXPECT_GT(std::abs((linear[0] - linear[1]) - (linear[1] - linear[2])), 1.0);
}

TEST(SvgPlot, TheLeftMarginMakesRoomForTheWidestTickLabel) {
  PlotPanel small = counts(false);
  small.series[0].points = {{0, 0.5}, {1, 2}};
  const double narrow = frame_left(meshstep::app::svg_figure({small}));
  const double wide = frame_left(meshstep::app::svg_figure({counts(false)}));  // "100000": six digits
  EXPECT_GE(wide, 34 + 6 * 6.4 - 0.01);
  EXPECT_GT(wide, narrow);
}

}  // namespace
