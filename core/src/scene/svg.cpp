// The SVG document: the header, the background, then one group per visible layer, in
// layer order, each filled by its part writer (svg_parts.hpp).
#include "meshstep/scene/svg.hpp"

#include <algorithm>

#include "scene/svg_parts.hpp"

namespace meshstep::scene {

namespace {

void write_layer(detail::SvgContext& c, Layer layer) {
  switch (layer) {
    case Layer::fill: detail::write_mesh_fill(c); break;
    case Layer::edges: detail::write_mesh_edges(c); break;
    default: break;
  }
  // Any layer may hold shapes; the words come after them, as in the GL renderer.
  for (const Shape& shape : c.scene.shapes)
    if (shape.layer == layer) detail::write_shape(c, shape);
  switch (layer) {
    case Layer::labels: detail::write_labels(c); break;
    case Layer::caption: detail::write_caption(c); break;
    case Layer::legend: detail::write_legend(c); break;
    default: break;
  }
}

}  // namespace

std::string to_svg(const Scene& scene, const Camera& camera) {
  detail::SvgText out;
  const int width = std::max(camera.width(), 0), height = std::max(camera.height(), 0);
  const detail::ScreenBox view{0.0, 0.0, static_cast<double>(width), static_cast<double>(height)};
  detail::SvgContext c{scene, camera, out, view, view.grown(detail::kGuardPx), {}, {}};
  // A mesh costs about 25 bytes per triangle for its fill and 15 for its edges.
  out.reserve((std::size_t{1} << 16) + 40 * scene.mesh.triangles.size());

  out.raw("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"");
  out.attr_number("width", width);
  out.attr_number("height", height);
  out.raw(" viewBox=\"0 0 ");
  out.number(width);
  out.ch(' ');
  out.number(height);
  out.raw("\" font-family=\"DejaVu Sans, sans-serif\">\n");

  if (scene.background.a > 0) {
    out.raw("<rect");
    out.attr("id", c.ids.unique("background"));
    out.attr_number("width", width);
    out.attr_number("height", height);
    out.paint("fill", scene.background);
    out.raw("/>\n");
  }

  c.mesh_screen.reserve(scene.mesh.points.size());
  for (const Point& p : scene.mesh.points) c.mesh_screen.push_back(camera.to_screen(p));

  for (std::size_t i = 0; i < kLayerCount; ++i) {
    const auto layer = static_cast<Layer>(i);
    if (!scene.visible.has(layer)) continue;
    out.raw("<g");
    out.attr("id", c.ids.unique(std::string("layer-") + name(layer)));
    out.raw(">\n");
    write_layer(c, layer);
    out.raw("</g>\n");
  }
  out.raw("</svg>\n");
  return out.take();
}

}  // namespace meshstep::scene
