// Where a scene's labels go in one picture, so that no label covers another or a vertex.
//
// A label asks for a place (its offset from its point); where that place would overlap a
// label already placed or cover a vertex marker, the label tries a few other places round
// its point, nearest first, and is left out when none is free. A name (a vertex's, a
// region's) would also rather not cross a segment: a place clear of them wins if there is
// one; the step's own words keep close to their points instead. Labels are placed in order
// of their priority (Label::priority, higher first), then in the scene's order, so the
// step's own words keep their place and vertex names give way; the result depends on
// nothing but the scene and the camera. The GL renderer and the SVG writer both draw what
// this returns, each measuring text its own way.
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>
#include <vector>

#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene {

// A line of text's extent at a size, in pixels.
struct TextExtent {
  double width = 0.0, ascent = 0.0, descent = 0.0;
};
using MeasureText = std::function<TextExtent(std::string_view text, double size_px)>;

// DejaVu Sans's usual advances, ascent and descent: for the SVG writer, which cannot measure
// text when it writes, and for tests.
double estimated_text_width(std::string_view text, double size_px);
TextExtent estimated_text_extent(std::string_view text, double size_px);

struct PlacedLabel {
  std::size_t label = 0;         // its index in Scene::labels
  double left = 0.0, baseline = 0.0;  // where its text starts, whole pixels
  double size_px = 0.0;          // its size at the scene's text scale
  // The box its halo covers: the text's extent and 2 pixels either side.
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

// The labels that show in a picture of the camera's size, in the scene's order. A label
// whose point is off the picture is left out, as one that finds no free place.
std::vector<PlacedLabel> place_labels(const Scene& scene, const Camera& camera, const MeasureText& measure);

}  // namespace meshstep::scene
