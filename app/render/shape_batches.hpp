// The overlay shapes of a scene as GPU-ready arrays: one array per kind of primitive for
// the whole scene, and a list of draws (one per shape) that says which range of which array
// to draw in which style and layer. Built when the shapes (or the frame) change, drawn every
// frame with one draw call per shape.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "meshstep/scene/scene.hpp"
#include "world_frame.hpp"

namespace meshstep::render {

// A corner of an overlay's filled triangle: local position and the triangle's colour.
struct TriangleVertex {
  std::array<float, 2> position;
  scene::Rgba color;
};
static_assert(sizeof(TriangleVertex) == 12);

struct LineInstance {
  std::array<float, 2> from, to;
};
struct CircleInstance {
  std::array<float, 2> center;
  float radius;
};
struct MarkerInstance {
  std::array<float, 2> position;
};

// A shape's style, copied (the scene it came from may be gone by the time it is drawn).
struct ShapeStyle {
  scene::Rgba color, fill{0, 0, 0, 0};
  float width_px = 1.5f;
  bool dashed = false;
  float marker_px = 6.0f;
  scene::Marker marker = scene::Marker::disc;
};

struct ShapeDraw {
  scene::Layer layer;
  scene::ShapeKind kind;
  ShapeStyle style;
  std::size_t first = 0, count = 0;  // in the kind's array; triangles count whole triangles
};

struct ShapeBatches {
  std::vector<TriangleVertex> triangles;  // 3 per triangle
  std::vector<LineInstance> lines;
  std::vector<CircleInstance> circles;
  std::vector<MarkerInstance> markers;
  std::vector<ShapeDraw> draws;  // in the scene's order; the renderer draws them layer by layer
};

// Fills `out` (its old contents dropped, its memory kept) from the scene's shapes (the
// highlighted faces among them: the scene builder makes them a triangles shape in the
// highlight layer). Incomplete primitives (a line's lone last point, a circle without a
// radius) are skipped.
void build_shape_batches(const scene::Scene& scene, const WorldFrame& frame, ShapeBatches& out);

}  // namespace meshstep::render
