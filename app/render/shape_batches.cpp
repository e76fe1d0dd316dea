#include "shape_batches.hpp"

namespace meshstep::render {

namespace {

ShapeStyle style_of(const scene::Shape& s) {
  return ShapeStyle{s.color, s.fill, s.width_px, s.dashed, s.marker_px, s.marker};
}

void add_triangle(ShapeBatches& out, const WorldFrame& frame, const Point& a, const Point& b, const Point& c,
                  const scene::Rgba& color) {
  out.triangles.push_back({frame.to_local(a), color});
  out.triangles.push_back({frame.to_local(b), color});
  out.triangles.push_back({frame.to_local(c), color});
}

}  // namespace

void build_shape_batches(const scene::Scene& scene, const WorldFrame& frame, ShapeBatches& out) {
  out.triangles.clear();
  out.lines.clear();
  out.circles.clear();
  out.markers.clear();
  out.draws.clear();

  for (const scene::Shape& shape : scene.shapes) {
    const auto& p = shape.points;
    ShapeDraw draw{shape.layer, shape.kind, style_of(shape), 0, 0};
    switch (shape.kind) {
      case scene::ShapeKind::triangles:
        draw.first = out.triangles.size() / 3;
        for (std::size_t i = 0; i + 2 < p.size(); i += 3) add_triangle(out, frame, p[i], p[i + 1], p[i + 2], shape.color);
        draw.count = out.triangles.size() / 3 - draw.first;
        break;
      case scene::ShapeKind::lines:
        draw.first = out.lines.size();
        for (std::size_t i = 0; i + 1 < p.size(); i += 2)
          out.lines.push_back({frame.to_local(p[i]), frame.to_local(p[i + 1])});
        draw.count = out.lines.size() - draw.first;
        break;
      case scene::ShapeKind::circles:
        draw.first = out.circles.size();
        for (std::size_t i = 0; i < p.size() && i < shape.radii.size(); ++i)
          out.circles.push_back({frame.to_local(p[i]), frame.to_local_length(shape.radii[i])});
        draw.count = out.circles.size() - draw.first;
        break;
      case scene::ShapeKind::markers:
        draw.first = out.markers.size();
        for (const Point& at : p) out.markers.push_back({frame.to_local(at)});
        draw.count = out.markers.size() - draw.first;
        break;
    }
    if (draw.count > 0) out.draws.push_back(draw);
  }
}

}  // namespace meshstep::render
