// The viewer's look for a room: the UI scale (Ctrl+= / Ctrl+-, --ui-scale) and the panels'
// colours for a theme. A scale is applied by rasterising the font again at the scaled pixel
// size and scaling a fresh copy of the base style's sizes: stretching a 16 px atlas
// (FontGlobalScale) blurs every letter on a projector. No GL here: the host uploads the
// rebuilt font atlas (Host::reload_fonts) before the next frame.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "meshstep/scene/scene.hpp"

namespace meshstep::viewer {

inline constexpr float kMinUiScale = 0.75f, kMaxUiScale = 3.0f, kUiScaleStep = 0.25f;
inline constexpr float kBaseFontPixels = 16.0f;  // the font's size at scale 1

// True for kMinUiScale..kMaxUiScale in steps of kUiScaleStep (all exact in binary).
bool valid_ui_scale(double scale);
// "1.5" -> 1.5; nullopt for anything that is not a valid scale.
std::optional<float> parse_ui_scale(std::string_view text);
// `scale` moved by `steps` steps, held in the range.
float step_ui_scale(float scale, int steps);
// "0.75", "1", "1.5": as the settings file and the state write it.
std::string format_ui_scale(float scale);

// "light", "dark", "high-contrast": the words of the settings file, scripts and the state.
const char* theme_name(scene::Theme theme);
std::optional<scene::Theme> parse_theme(std::string_view text);

struct UiLook {
  float scale = 1.0f;
  scene::Theme theme = scene::Theme::light;  // the panels are dark but for high_contrast
  friend bool operator==(const UiLook&, const UiLook&) = default;
};

// Rebuilds the font atlas at kBaseFontPixels * scale and sets the style: the base style
// (dark panels, or black on white for the high-contrast theme) with ScaleAllSizes(scale).
// Call outside a frame (not between ImGui::NewFrame and ImGui::Render), then upload the
// atlas again.
void apply_ui_look(const UiLook& look);
// The look apply_ui_look set last (the panels pick their own colours by its theme).
const UiLook& current_ui_look();

}  // namespace meshstep::viewer
