// Shapes in SVG: one group per shape (class and id from its role, its label as a tooltip),
// drawn as the GL renderer draws them (shaders/*.frag): strokes centred on the geometry,
// dashes of dash_pattern(width), circles' dashes stretched to fit the circumference.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "scene/svg_parts.hpp"

namespace meshstep::scene::detail {

namespace {

// How far a huge circle drawn as a polygon may stray from the true circle.
constexpr double kCircleTolerancePx = 0.05;

struct Dashes {
  double dash, gap;
};
// The same as shaders/common.glsl: long enough to read at any width.
Dashes dash_pattern(double width) { return {std::max(3.0 * width, 4.0), std::max(2.0 * width, 3.0)}; }

// A role as a CSS class and XML id: letters, digits, '_' and '-', not starting with a digit
// or '-'.
std::string css_name(std::string_view role) {
  std::string name;
  for (const char ch : role) {
    const bool keep = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '-';
    name += keep ? ch : '_';
  }
  if (!name.empty() && ((name[0] >= '0' && name[0] <= '9') || name[0] == '-')) name.insert(name.begin(), '_');
  return name;
}

bool stroked(const Shape& s) { return s.color.a > 0 && s.width_px > 0.0f; }

void write_dasharray(SvgText& out, Dashes d) {
  out.raw(" stroke-dasharray=\"");
  out.fine_number(d.dash);
  out.ch(' ');
  out.fine_number(d.gap);
  out.ch('"');
}

// The style every element of the shape shares, as attributes of its group.
void write_style(SvgText& out, const Shape& s) {
  switch (s.kind) {
    case ShapeKind::triangles:
      out.paint("fill", s.color);
      return;
    case ShapeKind::lines:
      out.attr("fill", "none");
      out.paint("stroke", s.color);
      out.attr_fine("stroke-width", s.width_px);
      // Dashes are cut square, as the GL shader cuts them (each segment starts on a dash);
      // whole lines end round.
      if (s.dashed) write_dasharray(out, dash_pattern(s.width_px));
      else out.raw(" stroke-linecap=\"round\" stroke-linejoin=\"round\"");
      return;
    case ShapeKind::circles:
      out.paint("fill", s.fill);
      out.paint("stroke", stroked(s) ? s.color : Rgba{0, 0, 0, 0});
      out.attr_fine("stroke-width", s.width_px);
      return;
    case ShapeKind::markers:
      out.paint("fill", s.marker == Marker::cross ? Rgba{0, 0, 0, 0} : s.fill);
      out.paint("stroke", stroked(s) ? s.color : Rgba{0, 0, 0, 0});
      out.attr_fine("stroke-width", s.width_px);
      if (s.marker == Marker::cross) out.raw(" stroke-linecap=\"round\"");
      return;
  }
}

void write_triangles(SvgContext& c, const Shape& s) {
  if (s.color.a == 0) return;
  const std::size_t rollback = c.out.size();
  c.out.raw("<path d=\"");
  PathData path(c.out);
  TriangleWriter triangles(c, path, 1.0);
  const auto& p = s.points;
  for (std::size_t i = 0; i + 2 < p.size(); i += 3) triangles.add(c.to_screen(p[i]), c.to_screen(p[i + 1]), c.to_screen(p[i + 2]));
  if (path.empty()) c.out.truncate(rollback);
  else c.out.raw("\"/>\n");
}

void write_lines(SvgContext& c, const Shape& s) {
  if (!stroked(s)) return;
  const std::size_t rollback = c.out.size();
  c.out.raw("<path d=\"");
  PathData path(c.out);
  SegmentWriter segments(c, path, 0.5 * s.width_px + 1.0);
  const auto& p = s.points;
  for (std::size_t i = 0; i + 1 < p.size(); i += 2) {
    // Solid segments that meet join into one polyline (round joins); dashed ones stay
    // apart, each starting its dashes afresh as in the GL renderer.
    const bool joins = !s.dashed && i > 0 && p[i] == p[i - 1];
    segments.add(c.to_screen(p[i]), c.to_screen(p[i + 1]), joins);
  }
  if (path.empty()) c.out.truncate(rollback);
  else c.out.raw("\"/>\n");
}

// A circle too large for the guard box: the part of its disc and of its outline that can
// show, as polygons cut to the guard box.
void write_huge_circle(SvgContext& c, const Shape& s, Point center, double radius, bool fill, bool ring) {
  const CircleOutline outline = circle_outline(center, radius, c.guard, kCircleTolerancePx);
  if (fill) {
    std::vector<Point> polygon = outline.points, clipped;
    if (!outline.closed) polygon.push_back(center);  // a slice of the disc, cut to the guard box below
    clip_polygon(polygon, c.guard, clipped);
    if (!clipped.empty()) {
      c.out.raw("<path stroke=\"none\" d=\"");
      PathData path(c.out);
      path.move_to(clipped.front());
      for (std::size_t i = 1; i < clipped.size(); ++i) path.line_to(clipped[i]);
      path.close();
      c.out.raw("\"/>\n");
    }
  }
  if (ring) {
    const std::size_t rollback = c.out.size();
    c.out.raw("<path fill=\"none\"");
    if (s.dashed) write_dasharray(c.out, dash_pattern(s.width_px));
    c.out.raw(" d=\"");
    PathData path(c.out);
    SegmentWriter segments(c, path, 0.5 * s.width_px + 1.0);
    const auto& p = outline.points;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) segments.add(p[i], p[i + 1], true);
    if (outline.closed && p.size() > 1) segments.add(p.back(), p.front(), true);
    if (path.empty()) c.out.truncate(rollback);
    else c.out.raw("\"/>\n");
  }
}

void write_circles(SvgContext& c, const Shape& s) {
  const bool ring = stroked(s), fill = s.fill.a > 0;
  if (!ring && !fill) return;
  const double half_width = ring ? 0.5 * s.width_px : 0.0;
  const ScreenBox& view = c.view;
  const std::size_t count = std::min(s.points.size(), s.radii.size());
  for (std::size_t i = 0; i < count; ++i) {
    const Point center = c.to_screen(s.points[i]);
    const double radius = s.radii[i] * c.camera.pixels_per_unit();
    if (!finite(center) || !std::isfinite(radius) || radius < 0.0) continue;
    // The nearest and the farthest point of the picture from the centre: the circle shows
    // when its outer rim reaches the picture and, unfilled, when the picture is not wholly
    // inside its hole.
    const double near_x = std::max({view.x0 - center.x, 0.0, center.x - view.x1});
    const double near_y = std::max({view.y0 - center.y, 0.0, center.y - view.y1});
    const double far_x = std::max(std::abs(center.x - view.x0), std::abs(center.x - view.x1));
    const double far_y = std::max(std::abs(center.y - view.y0), std::abs(center.y - view.y1));
    const double reach = radius + half_width + 1.0;
    if (std::hypot(near_x, near_y) > reach) continue;
    const bool ring_shows = ring && std::hypot(far_x, far_y) >= radius - half_width - 1.0;
    if (!fill && !ring_shows) continue;

    if (!c.guard.contains({center.x - reach, center.y - reach}) || !c.guard.contains({center.x + reach, center.y + reach})) {
      write_huge_circle(c, s, center, radius, fill, ring_shows);
      continue;
    }
    c.out.raw("<circle");
    c.out.attr_number("cx", center.x);
    c.out.attr_number("cy", center.y);
    c.out.attr_number("r", radius);
    const double circumference = 2.0 * std::numbers::pi * radius;
    if (ring && s.dashed && circumference > 0.01) {
      // As the GL shader: a whole number of dash periods round the circle, and dashes
      // counted from its leftmost point (an SVG circle's stroke starts at its rightmost,
      // half way round, going the same way).
      const Dashes d = dash_pattern(s.width_px);
      const double period = circumference / std::max(1.0, std::floor(circumference / (d.dash + d.gap) + 0.5));
      const double dash = d.dash * period / (d.dash + d.gap);
      write_dasharray(c.out, {dash, period - dash});
      c.out.attr_fine("stroke-dashoffset", std::fmod(0.5 * circumference, period));
    }
    c.out.raw("/>\n");
  }
}

// Every marker of the shape in one path; `size` across, as shaders/marker.frag draws them.
void write_markers(SvgContext& c, const Shape& s) {
  const bool cross = s.marker == Marker::cross;
  if (!stroked(s) && (cross || s.fill.a == 0)) return;
  const double r = 0.5 * s.marker_px;
  const ScreenBox near_view = c.view.grown(r + 0.5 * s.width_px + 1.0);
  const std::size_t rollback = c.out.size();
  c.out.raw("<path d=\"");
  PathData path(c.out);
  for (const Point& at : s.points) {
    const Point p = c.to_screen(at);
    if (!finite(p) || !near_view.contains(p)) continue;
    switch (s.marker) {
      case Marker::disc:
      case Marker::ring:
        path.circle(p, r);
        break;
      case Marker::square:
        path.move_to({p.x - r, p.y - r});
        path.line_to({p.x + r, p.y - r});
        path.line_to({p.x + r, p.y + r});
        path.line_to({p.x - r, p.y + r});
        path.close();
        break;
      case Marker::diamond:
        path.move_to({p.x, p.y - r});
        path.line_to({p.x + r, p.y});
        path.line_to({p.x, p.y + r});
        path.line_to({p.x - r, p.y});
        path.close();
        break;
      case Marker::cross: {
        const double arm = 0.75 * r;  // the diagonals of a square a little smaller than the size
        path.move_to({p.x - arm, p.y - arm});
        path.line_to({p.x + arm, p.y + arm});
        path.move_to({p.x + arm, p.y - arm});
        path.line_to({p.x - arm, p.y + arm});
        break;
      }
    }
  }
  if (path.empty()) c.out.truncate(rollback);
  else c.out.raw("\"/>\n");
}

}  // namespace

void write_shape(SvgContext& c, const Shape& s) {
  SvgText& out = c.out;
  out.raw("<g");
  if (const std::string name = css_name(s.role); !name.empty()) {
    out.attr("class", name);
    out.attr("id", c.ids.unique(name));
  }
  write_style(out, s);
  out.raw(">");
  if (!s.label.empty()) {
    out.raw("<title>");
    out.escaped(s.label);
    out.raw("</title>");
  }
  out.ch('\n');
  switch (s.kind) {
    case ShapeKind::triangles: write_triangles(c, s); break;
    case ShapeKind::lines: write_lines(c, s); break;
    case ShapeKind::circles: write_circles(c, s); break;
    case ShapeKind::markers: write_markers(c, s); break;
  }
  out.raw("</g>\n");
}

}  // namespace meshstep::scene::detail
