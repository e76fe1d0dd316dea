// The caption fits its picture (issue 29: the canvas's caption ran on under the viewer's
// side panel at UI scale 1.5): a caption wider than the picture is set smaller, down to 60%
// of its size, whole pixels; a caption that fits keeps its size.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

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

}  // namespace
}  // namespace meshstep::scene
