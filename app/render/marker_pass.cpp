#include "marker_pass.hpp"

#include <cstddef>

namespace meshstep::render {

// shaders/marker.frag numbers the kinds as scene::Marker does.
static_assert(static_cast<int>(scene::Marker::disc) == 0 && static_cast<int>(scene::Marker::ring) == 1 &&
              static_cast<int>(scene::Marker::square) == 2 && static_cast<int>(scene::Marker::cross) == 3 &&
              static_cast<int>(scene::Marker::diamond) == 4);

MarkerPass::MarkerPass()
    : program_("marker.vert", "marker.frag"),
      view_uniforms_(program_),
      kind_(program_.uniform("u_kind")),
      size_(program_.uniform("u_size")),
      half_width_(program_.uniform("u_half_width")),
      color_(program_.uniform("u_color")),
      fill_(program_.uniform("u_fill")),
      quads_({{0, 2, offsetof(MarkerInstance, position)}}) {}

void MarkerPass::draw(const View& view, const ShapeDraw& draw) const {
  using scene::Marker;
  const ShapeStyle& s = draw.style;
  // A disc, square or diamond without a fill colour is solid in its stroke colour; a ring
  // is hollow unless given a fill.
  const bool solid = s.marker == Marker::disc || s.marker == Marker::square || s.marker == Marker::diamond;
  const scene::Rgba fill = s.fill.a > 0 || !solid ? s.fill : s.color;
  program_.use();
  view_uniforms_.set(view);
  glUniform1i(kind_, static_cast<GLint>(s.marker));
  glUniform1f(size_, s.marker_px);
  glUniform1f(half_width_, 0.5f * s.width_px);
  set_color(color_, s.color);
  set_color(fill_, fill);
  quads_.draw(draw.first, draw.count);
}

}  // namespace meshstep::render
