// SVG output of a scene: vector figures for slides, papers and web pages.
//
// The same scene and camera as the GL renderer, drawn with SVG elements: triangles grouped
// by fill colour into one path per colour, mesh edges as one path (each edge once),
// segments, shapes and markers, labels, caption and legend as text. Coordinates are pixels
// rounded to 0.01, so a 100k-triangle mesh stays a few megabytes.
//
// The document (SVG 1.1, UTF-8; opens in browsers, rsvg-convert, Inkscape):
//   <svg width=W height=H viewBox="0 0 W H" font-family="DejaVu Sans, sans-serif">
//     <rect id="background"/>                  (none when the background is transparent)
//     <g id="layer-fill"> ... <g id="layer-legend">   one group per visible layer, in
//                                              Layer order; a layer switched off is absent
//   Layer "fill": one <path> per fill colour, its triangles as subpaths, stroked 0.75 px in
//     its own colour when opaque (covers the hairline seams renderers leave between paths).
//   Layer "edges": every mesh edge once, as polylines. Edges of triangles small on screen
//     fade as in the GL renderer (shaders/mesh.frag): one path per opacity step (a mesh of
//     triangles over 14 px is a single path).
//   Every other layer: its shapes, then its words. Scene::highlighted is not drawn by
//     itself: the builder draws those faces as a shape ("changed_faces").
//   Shapes: one <g class=ROLE id=ROLE[-n]> each (the role made a valid name; id unique in
//     the document), with <title>label</title> (a tooltip) and the style as attributes;
//     lines as one path (round caps; dashed: dash_pattern of shaders/common.glsl, square
//     cut, each segment starting on a dash), circles as <circle> (r = radius x pixels per
//     unit; dashes stretched to a whole number round the circle, as in the GL shader),
//     markers as one path (disc, ring, square, diamond: marker_px across; cross: the two
//     diagonals at 3/4 of that), triangles as one path.
//   Labels: <text> at to_screen(at) + (dx, dy) rounded to whole pixels: the left end of the
//     baseline; behind each a translucent box (the background at 160/255) sized by an
//     estimate of DejaVu Sans's advances.
//   Caption and legend: placed by layout() (layout.hpp), as the GL renderer places them;
//     the caption band and legend panel are the background at 200/255 and 225/255, text in
//     the caption colour (the theme's when that is transparent); a continuous legend bar is
//     a linearGradient of the stops, bottom to top, with 1-px ticks on its right.
//
// Primitives wholly outside the picture are left out; a primitive reaching more than
// 4096 px beyond it is cut there (huge circles become polygons), so zooming in never writes
// coordinates a renderer cannot handle. Non-finite coordinates leave their primitive out.
// Text is escaped (&, <, >, quotes); invalid UTF-8 becomes U+FFFD.
#pragma once

#include <string>

#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene {

// The SVG document (UTF-8), width x height = the camera's picture size.
std::string to_svg(const Scene& scene, const Camera& camera);

}  // namespace meshstep::scene
