// The parts of the SVG document, one writer per kind of content (svg.cpp puts them in
// layer order): the mesh's fill and edges, shapes, labels, caption and legend.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/scene.hpp"
#include "scene/svg_clip.hpp"
#include "scene/svg_text.hpp"

namespace meshstep::scene::detail {

// Element ids must be unique in a document: "flip_circle", then "flip_circle-2", ...
class IdRegistry {
 public:
  std::string unique(std::string_view base);

 private:
  std::set<std::string, std::less<>> used_;
};

// What every part writer needs.
struct SvgContext {
  const Scene& scene;
  const Camera& camera;
  SvgText& out;
  ScreenBox view;   // the picture: [0, width] x [0, height]
  ScreenBox guard;  // the picture grown by kGuardPx: nothing written reaches beyond it
  IdRegistry ids;
  std::vector<Point> mesh_screen;  // the mesh's points in pixels (filled by svg.cpp)

  Point to_screen(Point world) const { return camera.to_screen(world); }
};

inline bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Layer::fill: triangles grouped by colour, one path per colour.
void write_mesh_fill(SvgContext& c);
// Layer::edges: every mesh edge once (one path per fade step; usually a single path).
void write_mesh_edges(SvgContext& c);
// One shape as a group (class and id from its role).
void write_shape(SvgContext& c, const Shape& shape);
// Layer::labels: the scene's labels as text.
void write_labels(SvgContext& c);
// Layer::caption and Layer::legend, placed by layout.hpp.
void write_caption(SvgContext& c);
void write_legend(SvgContext& c);

// Colours the GL renderer uses too (app/render/overlay_text.cpp): the colour of text (the
// caption colour, or the theme's when that is transparent) and of what text sits on (the
// background, or the theme's, at `alpha`).
Rgba text_color(const Scene& scene);
Rgba panel_color(const Scene& scene, std::uint8_t alpha);

// Triangles as closed subpaths of `path`, all turning the same way on screen (so that
// nonzero filling never cancels one against another); cut to the guard box when they reach
// beyond it. Degenerate and invisible triangles are left out.
class TriangleWriter {
 public:
  TriangleWriter(const SvgContext& c, PathData& path, double visible_pad) : c_(c), path_(path), pad_(visible_pad) {}
  void add(Point a, Point b, Point c);

 private:
  const SvgContext& c_;
  PathData& path_;
  double pad_;
  std::vector<Point> polygon_, clipped_;
};

// Segments as "move, line" subpaths of `path`, joined into polylines when one starts where
// the last ended; cut to the guard box when they reach beyond it.
class SegmentWriter {
 public:
  SegmentWriter(const SvgContext& c, PathData& path, double visible_pad) : c_(c), path_(path), pad_(visible_pad) {}
  // `joins` says whether `a` is where the previous segment ended (the caller knows).
  void add(Point a, Point b, bool joins = false);
  // Forgets where the pen is: the next segment starts a subpath.
  void lift() { pen_down_ = false; }

 private:
  const SvgContext& c_;
  PathData& path_;
  double pad_;
  bool pen_down_ = false;
};

}  // namespace meshstep::scene::detail
