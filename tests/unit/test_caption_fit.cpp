// The caption fits its picture (issue 29: the canvas's caption ran on under the viewer's
// side panel at UI scale 1.5): a caption wider than the picture is set smaller, down to 60%
// of its size, whole pixels; a caption that fits keeps its size.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "meshstep/scene/label_placement.hpp"
#include "meshstep/scene/layout.hpp"

namespace meshstep::scene {
namespace {

const char* kLong = "refine \u00B7 step 26 of 50 \u00B7 segment 6-7 encroached by vertex 13: split at its midpoint; 3 flips";

TEST(CaptionFit, ALongCaptionIsSetSmallerToFitTheCanvasBesideThePanel) {
  Scene s;
  s.caption = kLong;
  s.text_scale = 1.5f;
  const int canvas = 768;  // 1280 less the side panel at UI scale 1.5
  const Layout l = layout(s, canvas, 720);
  ASSERT_TRUE(l.caption_band);
  EXPECT_LT(l.caption.size_px, 16.0 * 1.5);
  EXPECT_EQ(l.caption.size_px, std::floor(l.caption.size_px)) << "whole pixels";
  EXPECT_LE(l.caption.at.x + estimated_text_width(s.caption, l.caption.size_px), canvas - l.caption.at.x)
      << "ends inside the canvas, with the margin it starts with";
  // Still in the band.
  EXPECT_LT(l.caption.at.y, l.caption_band->h);
}

TEST(CaptionFit, ACaptionThatFitsKeepsItsSizeAndAVeryLongOneStopsShrinkingAt60Percent) {
  Scene s;
  s.caption = kLong;
  EXPECT_EQ(layout(s, 1280, 720).caption.size_px, 16.0);
  s.caption = std::string(400, 'x');
  EXPECT_EQ(layout(s, 1280, 720).caption.size_px, std::ceil(0.6 * 16.0));
}

// Runs side by side give each canvas half the window: a step's caption did not fit even at
// 60% and was cut at the picture's edge. It is wrapped, each line inside the picture.
TEST(CaptionFit, ACaptionTooLongEvenSmallerIsWrappedInsideTheBand) {
  Scene s;
  s.caption = kLong;
  const int canvas = 446;  // a pane of four runs side by side in a 1280x800 window
  const Layout l = layout(s, canvas, 290);
  ASSERT_TRUE(l.caption_band);
  ASSERT_GE(l.caption_lines.size(), 2u);
  ASSERT_EQ(l.caption_spots.size(), l.caption_lines.size());
  std::string joined;
  for (std::size_t i = 0; i < l.caption_lines.size(); ++i) {
    const std::string& line = l.caption_lines[i];
    const TextSpot& spot = l.caption_spots[i];
    EXPECT_LE(spot.at.x + estimated_text_width(line, spot.size_px), canvas - spot.at.x) << line;
    EXPECT_NE(line.rfind("\u00B7", 0), 0u) << "a line begins with a middle dot: " << line;
    EXPECT_GT(spot.size_px, std::ceil(0.6 * 16.0)) << "larger than the smallest one-line size";
    if (i > 0) EXPECT_GT(spot.at.y, l.caption_spots[i - 1].at.y);
    joined += (i ? " " : "") + line;
  }
  EXPECT_EQ(joined, s.caption) << "every word, in order";
  EXPECT_EQ(l.caption.at.y, l.caption_spots[0].at.y);
  // The band holds the last line, and the camera's fit keeps the mesh below the band.
  EXPECT_LT(l.caption_spots.back().at.y, l.caption_band->h);
  EXPECT_GT(l.margins.top, l.caption_band->h);
  // A caption that fits is one line, as before.
  s.caption = "refine \u00B7 step 26 of 50";
  EXPECT_TRUE(layout(s, canvas, 290).caption_lines.empty());
}

TEST(CaptionFit, AWrappedCaptionStopsAtThreeLinesAndSaysSo) {
  Scene s;
  for (int i = 0; i < 60; ++i) s.caption += "word ";
  const Layout l = layout(s, 300, 200);
  ASSERT_EQ(l.caption_lines.size(), 3u);
  const std::string& last = l.caption_lines.back();
  EXPECT_EQ(last.substr(last.size() - 3), "...");
}

}  // namespace
}  // namespace meshstep::scene
