// The scene: everything one picture shows, in world coordinates, without any GL.
//
// It is the one seam between the algorithms and every picture. The scene builder
// (scene/build.hpp) makes it from a mesh and, optionally, the current moment of a replay;
// the OpenGL renderer, the SVG writer, the viewer and the tests all read it. Tests check the
// scene exactly (which faces are highlighted, where each circle is) before any pixel.
//
// A scene is a mesh (filled triangles with a colour each, and their edges) plus an ordered
// list of shapes drawn over it. Every shape belongs to a layer, and a layer can be switched
// off. Sizes of strokes and markers are in pixels (they stay readable at any zoom); every
// position and every circle radius is in world units.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "meshstep/geometry/point.hpp"

namespace meshstep::scene {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba&, const Rgba&) = default;
};

// The layers, in drawing order (each switchable; see LayerSet).
enum class Layer : std::uint8_t {
  fill,       // triangles filled by the chosen quantity
  edges,      // mesh edges
  voronoi,    // the mesh's dual: circumcenters, their edges, rays on the hull, sites (off by default)
  highlight,  // the faces the current step changed
  overlay,    // the current event explained (bad triangle, Lepp path, circles, flips...)
  segments,   // constrained edges (input segments and their pieces)
  vertices,   // input and Steiner vertices
  holes,      // the hole points of the input
  labels,     // text placed in the world (Lepp order, point names)
  caption,    // the one-line caption of the current step
  legend,     // the colour bar and the numbers behind the colours
  count_
};
inline constexpr std::size_t kLayerCount = static_cast<std::size_t>(Layer::count_);

const char* name(Layer layer);
// Parses a layer name as name(layer) prints it; nullopt when it is not one.
std::optional<Layer> parse_layer(std::string_view text);

class LayerSet {
 public:
  static LayerSet all() { return LayerSet((1u << kLayerCount) - 1); }
  // What a picture shows unless asked otherwise: every layer but the Voronoi diagram, which
  // is drawn over the mesh only when a lecture wants it.
  static LayerSet standard() { return all().set(Layer::voronoi, false); }
  static LayerSet none() { return LayerSet(0); }
  bool has(Layer l) const { return bits_ >> static_cast<unsigned>(l) & 1u; }
  LayerSet& set(Layer l, bool on = true) {
    const std::uint32_t bit = 1u << static_cast<unsigned>(l);
    bits_ = on ? bits_ | bit : bits_ & ~bit;
    return *this;
  }
  std::uint32_t bits() const { return bits_; }
  friend bool operator==(const LayerSet&, const LayerSet&) = default;

 private:
  explicit LayerSet(std::uint32_t bits) : bits_(bits) {}
  std::uint32_t bits_;
};

// What fills the triangles.
// height: the mean height of a triangle's corners (a terrain's or a surface's log, whose
// vertices have heights; others have none to show).
enum class ColorBy : std::uint8_t { none, angle, quality, area, region, age, height, count_ };
const char* name(ColorBy c);
std::optional<ColorBy> parse_color_by(std::string_view text);

// high_contrast: for a projector (white, opaque black lines thick enough to see from the
// back of a room, the light theme's strong overlay colours).
enum class Theme : std::uint8_t { light, dark, high_contrast };

// The numbers behind the colours: a bar of colour stops (continuous) or swatches
// (categorical), with labelled ticks.
struct Legend {
  std::string title;                 // "smallest angle (degrees)"
  bool categorical = false;
  std::vector<Rgba> colors;          // continuous: evenly spaced stops, bottom to top of the scale
  struct Tick {
    double at = 0.0;                 // 0..1 along the bar (categorical: the swatch's centre)
    std::string text;
    bool emphasized = false;         // drawn stronger: the bound on the quality scale
  };
  std::vector<Tick> ticks;
};

// The mesh: its points, its triangles (counterclockwise), a fill colour per triangle and
// the quantity behind it, and how its edges are stroked.
struct MeshLayer {
  std::vector<Point> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Rgba> fill;       // one per triangle
  std::vector<double> values;   // the quantity behind each fill colour (empty for ColorBy::none)
  std::vector<double> region;   // each triangle's regional attribute (empty: the input has no regions)
  Rgba edge_color;
  float edge_width_px = 1.0f;
  // The triangles are in drawing order, back to front (a 3D view, scene/surface_view.hpp):
  // each must be drawn with its edges before the next, so that nearer ones cover them. The
  // GL renderer always draws in index order, fill and edges in one pass; the SVG writer
  // writes such a mesh triangle by triangle instead of grouping it by colour.
  bool painter_order = false;
};

enum class ShapeKind : std::uint8_t {
  triangles,  // filled: 3 points each (translucent colours read through)
  lines,      // stroked: 2 points each
  circles,    // stroked (and filled when fill.a > 0): a centre each, radii[i] in world units
  markers,    // a point each, marker_px across
};

enum class Marker : std::uint8_t { disc, ring, square, cross, diamond };

// One group of primitives of one style. `role` names what it shows ("bad_triangle",
// "lepp_path", "flip_circle", ...): tests look shapes up by it, the SVG writer uses it as
// the element's class, and `label` says it in words for a key.
struct Shape {
  Layer layer = Layer::overlay;
  ShapeKind kind = ShapeKind::lines;
  std::string role;
  std::string label;
  Rgba color;                  // stroke (lines, circles, marker outline) or fill (triangles)
  Rgba fill{0, 0, 0, 0};       // circles and markers: the inside (a == 0: none)
  float width_px = 1.5f;       // lines, circles, marker outlines
  bool dashed = false;         // lines and circles
  float marker_px = 6.0f;      // markers
  Marker marker = Marker::disc;
  std::vector<Point> points;
  std::vector<double> radii;   // circles
};

// Text anchored at a world point, offset in pixels, drawn at a fixed pixel size.
struct Label {
  Point at;
  std::string text;
  Rgba color;
  float size_px = 14.0f;
  float dx_px = 0.0f, dy_px = 0.0f;  // screen offset (y down)
  // Which labels give way where they would overlap (scene/label_placement.hpp): the lower
  // moves or goes first. Vertex names 0, region names 1, the step's own words 2.
  std::uint8_t priority = 2;
};

struct Scene {
  Theme theme = Theme::light;
  Rgba background;
  // Of the mesh and every shape: what a camera fits. Circles count only as far as the box of
  // everything else grown by a tenth of its larger side on each side, so that the circle of
  // a nearly flat triangle (radius a thousand times the mesh) cannot shrink the mesh to a dot.
  BBox bounds;
  MeshLayer mesh;
  std::vector<Shape> shapes;  // drawn in order within their layer, layers in Layer order
  std::vector<Label> labels;
  std::string caption;        // one line: "refine · step 12 of 340 · ..."
  Rgba caption_color;
  // A guided tour's caption (teach/tour.hpp): a few sentences on a band across the picture's
  // bottom, wrapped to its width (layout.hpp), whatever layers are on. Empty: no band.
  std::string narration;
  std::optional<Legend> legend;
  LayerSet visible = LayerSet::standard();
  // The caption, the legend and the labels drawn this many times their size (the viewer's
  // UI scale, so that the canvas's words read as far as its panels' do). 1 in a file.
  float text_scale = 1.0f;

  // Indices in mesh.triangles of the faces the current step made or changed.
  std::vector<std::uint32_t> highlighted;

  // The first shape with this role, or nullptr. A role may have several shapes: its
  // translucent faces first, then their outline; faded earlier flips, then the latest.
  const Shape* find(std::string_view role) const;
  // Every shape with this role, in drawing order.
  std::vector<const Shape*> find_all(std::string_view role) const;
};

}  // namespace meshstep::scene
