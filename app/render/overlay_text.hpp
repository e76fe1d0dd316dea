// The words of a picture in pixels, into a UiBatch: the caption on its translucent band, the
// labels at their world points, the legend (a colour bar with ticks and a title, or
// swatches) on its panel. The caption and the legend are placed by scene::layout, which the
// SVG writer uses too, so that both pictures agree.
#pragma once

#include <string_view>

#include "font_atlas.hpp"
#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/scene/scene.hpp"
#include "ui_batch.hpp"

namespace meshstep::render {

void add_caption(const scene::Scene& scene, const scene::Layout& layout, FontCache& fonts, UiBatch& batch);
// A tour's narration (Scene::narration) on its band at the bottom, in kNoteLayer: it shows
// whatever layers a stop switches off.
void add_narration(const scene::Scene& scene, const scene::Layout& layout, FontCache& fonts, UiBatch& batch);
void add_legend(const scene::Scene& scene, const scene::Layout& layout, FontCache& fonts, UiBatch& batch);
void add_labels(const scene::Scene& scene, const scene::Camera& camera, FontCache& fonts, UiBatch& batch);

// A note on the picture itself, at its bottom left, whatever layers are on ("approximate
// while scrubbing"): its items go to kNoteLayer, which no scene layer is, drawn last.
inline constexpr scene::Layer kNoteLayer = scene::Layer::count_;
void add_note(const scene::Scene& scene, int height, std::string_view note, FontCache& fonts, UiBatch& batch);

}  // namespace meshstep::render
