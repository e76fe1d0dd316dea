#include "ui_look.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "render/embedded_files.hpp"

namespace meshstep::viewer {

bool valid_ui_scale(double scale) {
  if (!(scale >= kMinUiScale - 1e-9 && scale <= kMaxUiScale + 1e-9)) return false;
  const double steps = scale / kUiScaleStep;
  return std::abs(steps - std::round(steps)) < 1e-9;
}

std::optional<float> parse_ui_scale(std::string_view text) {
  const std::string s(text);
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !valid_ui_scale(v)) return std::nullopt;
  return static_cast<float>(v);
}

float step_ui_scale(float scale, int steps) {
  const float snapped = std::round(scale / kUiScaleStep) * kUiScaleStep;
  return std::clamp(snapped + static_cast<float>(steps) * kUiScaleStep, kMinUiScale, kMaxUiScale);
}

std::string format_ui_scale(float scale) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%g", static_cast<double>(scale));
  return buf;
}

const char* theme_name(scene::Theme theme) {
  switch (theme) {
    case scene::Theme::dark: return "dark";
    case scene::Theme::high_contrast: return "high-contrast";
    case scene::Theme::light: break;
  }
  return "light";
}

std::optional<scene::Theme> parse_theme(std::string_view text) {
  if (text == "light") return scene::Theme::light;
  if (text == "dark") return scene::Theme::dark;
  if (text == "high-contrast") return scene::Theme::high_contrast;
  return std::nullopt;
}

namespace {

// Black on white with saturated accents: a projector turns mid greys into one grey.
void high_contrast_colors(ImGuiStyle& style) {
  ImGui::StyleColorsLight(&style);
  ImVec4* c = style.Colors;
  const ImVec4 black(0, 0, 0, 1), white(1, 1, 1, 1), blue(0.0f, 0.30f, 0.70f, 1.0f);
  c[ImGuiCol_Text] = black;
  c[ImGuiCol_TextDisabled] = ImVec4(0.25f, 0.25f, 0.25f, 1);
  c[ImGuiCol_WindowBg] = white;
  c[ImGuiCol_ChildBg] = white;
  c[ImGuiCol_PopupBg] = white;
  c[ImGuiCol_Border] = black;
  c[ImGuiCol_FrameBg] = ImVec4(0.90f, 0.90f, 0.90f, 1);
  c[ImGuiCol_TitleBg] = c[ImGuiCol_TitleBgActive] = ImVec4(0.85f, 0.85f, 0.85f, 1);
  c[ImGuiCol_Header] = ImVec4(0.80f, 0.86f, 0.95f, 1);
  c[ImGuiCol_CheckMark] = c[ImGuiCol_SliderGrab] = c[ImGuiCol_PlotLines] = c[ImGuiCol_PlotHistogram] = blue;
  c[ImGuiCol_Button] = ImVec4(0.85f, 0.85f, 0.85f, 1);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.70f, 0.80f, 0.95f, 1);
}

}  // namespace

namespace {
UiLook g_look;  // the UI thread's: ImGui has one context, used from that thread only
}  // namespace

const UiLook& current_ui_look() { return g_look; }

void apply_ui_look(const UiLook& look) {
  g_look = look;
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  const std::string_view font = render::embedded_file("DejaVuSans.ttf");
  ImFontConfig config;
  config.FontDataOwnedByAtlas = false;  // the bytes live in the program
  static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x2190, 0x2193, 0x00B0, 0x00B7, 0};
  io.Fonts->AddFontFromMemoryTTF(const_cast<char*>(font.data()), static_cast<int>(font.size()),
                                 std::round(kBaseFontPixels * look.scale), &config, kRanges);
  io.Fonts->Build();

  // A fresh base style each time: scaling the current one would compound the roundings.
  ImGuiStyle style;
  if (look.theme == scene::Theme::high_contrast) high_contrast_colors(style);
  else ImGui::StyleColorsDark(&style);
  style.WindowRounding = 0.0f;
  style.FrameRounding = 3.0f;
  style.ItemSpacing = ImVec2(8, 5);
  if (look.theme == scene::Theme::high_contrast) style.FrameBorderSize = 1.0f;
  style.ScaleAllSizes(look.scale);
  ImGui::GetStyle() = style;
}

}  // namespace meshstep::viewer
