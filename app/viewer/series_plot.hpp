// A series of values (one per step of a run) drawn as a line plot, as ImGui::PlotLines
// draws one, but rasterised on the CPU into a picture once, and shown as one image from then
// on. ImGui's plot is a thin antialiased line a pixel column, drawn again every frame:
// llvmpipe spends about half a millisecond a plot on it, 4 ms of an 18 ms idle frame with
// four runs side by side (eight plots). The cursor's line, the overlay text and the hover's
// tooltip are drawn over the image each frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <imgui.h>

#include "meshstep/scene/image.hpp"
#include "picture_texture.hpp"

namespace meshstep::viewer {

// The plot of `values` on the scale lo..hi (lo at the bottom row, hi at the top) in a picture
// of width x height: each pixel column spans the values that fall in it, joined to the last
// value of the column before, in `line` over `background` (RGBA, 0xAABBGGRR as ImU32).
// NaN values are gaps. `out` is resized and overwritten (its storage reused).
void raster_series(const std::vector<float>& values, float lo, float hi, int width, int height, std::uint32_t background,
                   std::uint32_t line, scene::Image& out);

class SeriesPlot {
 public:
  // Draws the plot as an ImGui item of `size` (pixels) at the cursor, with the cursor's
  // value index `at` marked by a red line and `overlay` (may be null) centred at its top.
  // The picture is made again only when the values (their `generation`, address or count),
  // the scale, the size or the theme's colours change: an idle frame allocates nothing.
  // Needs the UI's GL context.
  void draw(const char* id, const std::vector<float>& values, std::uint64_t generation, float lo, float hi, ImVec2 size,
            std::size_t at, const char* overlay);

 private:
  struct Key {
    std::uint64_t generation = 0;
    const float* data = nullptr;
    std::size_t count = 0;
    float lo = 0, hi = 0;
    int width = 0, height = 0;
    std::uint32_t background = 0, line = 0;
    bool operator==(const Key&) const = default;
  };
  Key key_;
  scene::Image image_;
  PictureTexture texture_;
};

}  // namespace meshstep::viewer
