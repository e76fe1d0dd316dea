// How every part of a scene looks, per theme: one table, so that the colours keep one
// meaning across every picture.
//
// The overlays speak one colour language (Okabe-Ito hues, safe for colour-blind readers,
// strong enough to stand out over any fill, with thicker strokes than the mesh):
//   vermillion      what is wrong and being fixed: the bad triangle, the encroached segment,
//                   the edge bisected, the segment being recovered, a failed criterion, a
//                   removed vertex (and their circles)
//   yellow (ringed) the point chosen or inserted
//   reddish purple  what is rejected or replaced: alternatives, edges flipped away, the
//                   encroaching point, the Lepp terminal edge about to be split
//   blue            what is new: edges after a flip, the cavity's boundary, new edges
//   bluish green    paths and fans: the Lepp path, the new fan, the in-circle test's circle
//   orange          regions taken out: a cavity, a vertex's star, the terminal triangles
//   sky blue        searching: the point location walk and the face it found
// The dark theme uses lighter variants of the dark hues (blue, vermillion) to keep their
// contrast on a dark background.
#pragma once

#include "meshstep/scene/colormap.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene::detail {

// The mesh, the input and the text.
struct BaseStyle {
  Rgba background;
  Rgba neutral_fill;  // ColorBy::none
  Rgba edge;          // translucent: reads through any fill
  float edge_width_px;
  Rgba segment;
  float segment_width_px;
  Rgba input_vertex, steiner_vertex, vertex_outline;
  Rgba hole;
  Rgba region_point;
  Rgba text;
  // The Voronoi layer, drawn as a textbook draws it beside the triangulation: the diagram in
  // one strong colour, the sites as dots, the Delaunay edges under it lighter (faint_edge).
  Rgba voronoi;
  float voronoi_width_px;
  Rgba voronoi_site;
  Rgba faint_edge;
};

// One stroke-and-fill pair of an overlay role: `fill` for its translucent triangles,
// `stroke` for its lines, circles and outlines.
struct Paint {
  Rgba stroke;
  Rgba fill;
};

struct OverlayStyle {
  Paint located, walk;
  Paint bad, circumcircle;
  Paint selected, alternative;  // marker fill (stroke: its outline)
  Paint lepp, terminal_triangles, terminal_edge;
  Paint cavity, new_fan, cavity_boundary;
  Paint flip_before, flip_after, flip_circle;
  Paint encroached, diametral, encroacher, split;
  Paint bisected, bisection_new;
  Paint recovered;  // the segment a recovery step is making an edge
  Paint removed, star;
  Paint failed;
  Paint changed;
  Rgba marker_outline;  // round the filled markers
  Rgba label;           // world labels (Lepp order, point names, measured values)
  std::uint8_t faded_alpha;  // earlier flips of a step, behind the latest
};

const BaseStyle& base_style(Theme theme);
const OverlayStyle& overlay_style(Theme theme);

// Stroke widths and marker sizes, in pixels, shared by both themes.
namespace px {
inline constexpr float outline = 2.5f;      // round a highlighted triangle
inline constexpr float thin = 1.5f;         // secondary outlines, faded flips
inline constexpr float stroke = 2.5f;       // circles, flipped edges
inline constexpr float thick = 5.0f;        // the edge that matters (terminal, encroached)
inline constexpr float point = 13.0f;       // the chosen point
inline constexpr float small_point = 11.0f; // other named points
inline constexpr float label = 13.0f;
}  // namespace px

}  // namespace meshstep::scene::detail
