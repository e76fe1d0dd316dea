#include "circle_pass.hpp"

#include <cstddef>

namespace meshstep::render {

CirclePass::CirclePass()
    : program_("circle.vert", "circle.frag"),
      view_uniforms_(program_),
      color_(program_.uniform("u_color")),
      fill_(program_.uniform("u_fill")),
      half_width_(program_.uniform("u_half_width")),
      dashed_(program_.uniform("u_dashed")),
      quads_({{0, 2, offsetof(CircleInstance, center)}, {1, 1, offsetof(CircleInstance, radius)}}) {}

void CirclePass::draw(const View& view, const ShapeDraw& draw) const {
  program_.use();
  view_uniforms_.set(view);
  set_color(color_, draw.style.color);
  set_color(fill_, draw.style.fill);
  glUniform1f(half_width_, 0.5f * draw.style.width_px);
  glUniform1f(dashed_, draw.style.dashed ? 1.0f : 0.0f);
  quads_.draw(draw.first, draw.count);
}

}  // namespace meshstep::render
