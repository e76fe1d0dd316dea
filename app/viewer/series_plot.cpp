#include "series_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace meshstep::viewer {

void raster_series(const std::vector<float>& values, float lo, float hi, int width, int height, std::uint32_t background,
                   std::uint32_t line, scene::Image& out) {
  out.width = std::max(1, width);
  out.height = std::max(1, height);
  out.rgba.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4);
  const auto put = [&](int x, int y, std::uint32_t colour) {
    std::memcpy(out.row(y) + static_cast<std::size_t>(x) * 4, &colour, 4);  // ImU32 is R, G, B, A in memory
  };
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) put(x, y, background);
  if (values.empty()) return;
  const float span = hi > lo ? hi - lo : 1.0f;
  // The row of a value: lo on the bottom row, hi on the top one, clamped into the picture.
  const auto row_of = [&](float v) {
    const float t = std::clamp((v - lo) / span, 0.0f, 1.0f);
    return static_cast<int>(std::lround((1.0f - t) * static_cast<float>(out.height - 1)));
  };
  const std::size_t n = values.size();
  float last = NAN;  // the last value of the column before
  for (int x = 0; x < out.width; ++x) {
    // The values of this column: [first, end), at least one.
    const std::size_t first = n * static_cast<std::size_t>(x) / static_cast<std::size_t>(out.width);
    const std::size_t end = std::max(first + 1, n * static_cast<std::size_t>(x + 1) / static_cast<std::size_t>(out.width));
    float low = last, high = last;
    for (std::size_t i = first; i < std::min(end, n); ++i) {
      const float v = values[i];
      if (std::isnan(v)) continue;
      low = std::isnan(low) ? v : std::min(low, v);
      high = std::isnan(high) ? v : std::max(high, v);
      last = v;
    }
    if (std::isnan(low)) continue;
    for (int y = row_of(high); y <= row_of(low); ++y) put(x, y, line);
  }
}

void SeriesPlot::draw(const char* id, const std::vector<float>& values, std::uint64_t generation, float lo, float hi,
                      ImVec2 size, std::size_t at, const char* overlay) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const Key key{generation,
                values.data(),
                values.size(),
                lo,
                hi,
                std::max(1, static_cast<int>(size.x)),
                std::max(1, static_cast<int>(size.y)),
                ImGui::ColorConvertFloat4ToU32(style.Colors[ImGuiCol_FrameBg]),
                ImGui::ColorConvertFloat4ToU32(style.Colors[ImGuiCol_PlotLines])};
  if (!(key == key_) || texture_.empty()) {
    raster_series(values, lo, hi, key.width, key.height, key.background, key.line, image_);
    texture_.upload(image_);
    key_ = key;
  }
  ImGui::PushID(id);
  const ImVec2 min = ImGui::GetCursorScreenPos();
  ImGui::Image(texture_.id(), ImVec2(static_cast<float>(key.width), static_cast<float>(key.height)));
  ImDrawList* draw = ImGui::GetWindowDrawList();
  if (!values.empty()) {
    const std::size_t last = values.size() - 1;
    const float per_value = static_cast<float>(key.width) / static_cast<float>(std::max<std::size_t>(1, last));
    const float x = min.x + per_value * static_cast<float>(std::min(at, last));
    draw->AddLine(ImVec2(x, min.y), ImVec2(x, min.y + static_cast<float>(key.height)), IM_COL32(255, 60, 60, 255), 1.5f);
    if (ImGui::IsItemHovered()) {
      const float t = (ImGui::GetIO().MousePos.x - min.x) / static_cast<float>(key.width);
      const auto i = static_cast<std::size_t>(std::clamp(t, 0.0f, 1.0f) * static_cast<float>(last) + 0.5f);
      ImGui::SetTooltip("step %zu: %.6g", i, static_cast<double>(values[i]));
    }
  }
  if (overlay) {
    const ImVec2 text = ImGui::CalcTextSize(overlay);
    draw->AddText(ImVec2(min.x + (static_cast<float>(key.width) - text.x) * 0.5f, min.y + style.FramePadding.y),
                  ImGui::GetColorU32(ImGuiCol_Text), overlay);
  }
  ImGui::PopID();
}

}  // namespace meshstep::viewer
