// SVG output of a scene: vector figures for slides, papers and web pages.
//
// The same scene and camera as the GL renderer, drawn with SVG elements: triangles grouped
// by fill colour into one path per colour, mesh edges as one path (each edge once),
// segments, shapes and markers, labels, caption and legend as text. Coordinates are pixels
// rounded to 0.01, so a 100k-triangle mesh stays a few megabytes.
#pragma once

#include <string>

#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene {

// The SVG document (UTF-8), width x height = the camera's picture size.
std::string to_svg(const Scene& scene, const Camera& camera);

}  // namespace meshstep::scene
