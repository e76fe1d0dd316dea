// The words of the picture in SVG: labels at their world points, the caption on its band,
// the legend on its panel. Placed by layout.hpp (the caption and legend) and by the same
// rules as the GL renderer (app/render/overlay_text.cpp: colours, label halos).
#include <algorithm>
#include <cmath>
#include <string>

#include "meshstep/scene/colormap.hpp"
#include "meshstep/scene/label_placement.hpp"
#include "meshstep/scene/layout.hpp"
#include "scene/svg_parts.hpp"

namespace meshstep::scene::detail {

namespace {

void write_rect(SvgText& out, double x, double y, double w, double h, Rgba fill) {
  out.raw("<rect");
  out.attr_number("x", x);
  out.attr_number("y", y);
  out.attr_number("width", std::max(w, 0.0));
  out.attr_number("height", std::max(h, 0.0));
  out.paint("fill", fill);
  out.raw("/>\n");
}

void write_text(SvgText& out, Point at, double size_px, bool anchor_end, Rgba color, std::string_view text) {
  out.raw("<text");
  out.attr_number("x", at.x);
  out.attr_number("y", at.y);
  out.attr_fine("font-size", size_px);
  if (anchor_end) out.attr("text-anchor", "end");
  out.paint("fill", color);
  out.ch('>');
  out.escaped(text);
  out.raw("</text>\n");
}

void write_legend_bar(SvgContext& c, const Legend& legend, const Rect& bar, Rgba ink) {
  SvgText& out = c.out;
  const std::size_t n = legend.colors.size();
  if (n == 0) return;
  write_rect(out, bar.x - 1.0, bar.y - 1.0, bar.w + 2.0, bar.h + 2.0, with_alpha(ink, 90));  // a frame
  if (n == 1) {
    write_rect(out, bar.x, bar.y, bar.w, bar.h, legend.colors[0]);
    return;
  }
  // Evenly spaced stops from the bottom (the first colour) to the top.
  const std::string id = c.ids.unique("legend-gradient");
  out.raw("<defs><linearGradient");
  out.attr("id", id);
  out.raw(" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">");
  for (std::size_t i = 0; i < n; ++i) {
    out.raw("<stop");
    out.attr_fine("offset", static_cast<double>(i) / static_cast<double>(n - 1));
    out.attr_color("stop-color", legend.colors[i]);
    if (legend.colors[i].a != 255) out.attr_fine("stop-opacity", legend.colors[i].a / 255.0);
    out.raw("/>");
  }
  out.raw("</linearGradient></defs>\n<rect");
  out.attr_number("x", bar.x);
  out.attr_number("y", bar.y);
  out.attr_number("width", bar.w);
  out.attr_number("height", bar.h);
  out.raw(" fill=\"url(#");
  out.raw(id);
  out.raw(")\"/>\n");
}

}  // namespace

Rgba text_color(const Scene& s) {
  if (s.caption_color.a > 0) return s.caption_color;
  return s.theme == Theme::dark ? Rgba{235, 235, 235, 255} : Rgba{25, 25, 25, 255};
}

Rgba panel_color(const Scene& s, std::uint8_t alpha) {
  if (s.background.a > 0) return with_alpha(s.background, alpha);
  return s.theme == Theme::dark ? Rgba{30, 30, 30, alpha} : Rgba{255, 255, 255, alpha};
}

void write_labels(SvgContext& c) {
  const Rgba halo = panel_color(c.scene, 160);
  // Placed as the GL renderer places them (scene/label_placement.hpp), measured by estimate.
  for (const PlacedLabel& p : place_labels(c.scene, c.camera, estimated_text_extent)) {
    const Label& label = c.scene.labels[p.label];
    // A translucent box behind the text, so that it reads over the mesh.
    write_rect(c.out, p.x0, p.y0, p.x1 - p.x0, p.y1 - p.y0, halo);
    write_text(c.out, {p.left, p.baseline}, p.size_px, false, label.color, label.text);
  }
}

void write_caption(SvgContext& c) {
  const Layout layout = scene::layout(c.scene, c.camera.width(), c.camera.height());
  if (!layout.caption_band) return;
  const Rect& band = *layout.caption_band;
  write_rect(c.out, band.x, band.y, band.w, band.h, panel_color(c.scene, 200));
  if (layout.caption_lines.empty()) {
    write_text(c.out, layout.caption.at, layout.caption.size_px, layout.caption.anchor_end, text_color(c.scene), c.scene.caption);
    return;
  }
  for (std::size_t i = 0; i < layout.caption_lines.size(); ++i) {
    const TextSpot& spot = layout.caption_spots[i];
    write_text(c.out, spot.at, spot.size_px, spot.anchor_end, text_color(c.scene), layout.caption_lines[i]);
  }
}

void write_legend(SvgContext& c) {
  const Layout layout = scene::layout(c.scene, c.camera.width(), c.camera.height());
  if (!layout.legend || !c.scene.legend) return;
  const LegendLayout& place = *layout.legend;
  const Legend& legend = *c.scene.legend;
  const Rgba ink = text_color(c.scene);
  const Rect& panel = place.panel;
  write_rect(c.out, panel.x - 1.0, panel.y - 1.0, panel.w + 2.0, panel.h + 2.0, with_alpha(ink, 40));  // a hairline frame
  write_rect(c.out, panel.x, panel.y, panel.w, panel.h, panel_color(c.scene, 225));

  if (legend.categorical) {
    for (std::size_t i = 0; i < place.swatches.size() && i < legend.colors.size(); ++i) {
      const Rect& box = place.swatches[i];
      write_rect(c.out, box.x, box.y, box.w, box.h, legend.colors[i]);
    }
  } else {
    write_legend_bar(c, legend, place.bar, ink);
    // Tick marks from the bar's right side, one pixel thick, ending at their y.
    for (const double y : place.tick_y) write_rect(c.out, place.bar.x + place.bar.w, y - 1.0, place.tick_length, 1.0, ink);
  }
  for (std::size_t i = 0; i < place.ticks.size() && i < legend.ticks.size(); ++i) {
    const TextSpot& spot = place.ticks[i];
    write_text(c.out, spot.at, spot.size_px, spot.anchor_end, ink, legend.ticks[i].text);
  }
  if (!legend.title.empty())
    write_text(c.out, place.title.at, place.title.size_px, place.title.anchor_end, ink, legend.title);
}

}  // namespace meshstep::scene::detail
