#include "line_pass.hpp"

#include <cstddef>

namespace meshstep::render {

LinePass::LinePass()
    : program_("line.vert", "line.frag"),
      view_uniforms_(program_),
      color_(program_.uniform("u_color")),
      half_width_(program_.uniform("u_half_width")),
      dashed_(program_.uniform("u_dashed")),
      quads_({{0, 2, offsetof(LineInstance, from)}, {1, 2, offsetof(LineInstance, to)}}) {}

void LinePass::draw(const View& view, const ShapeDraw& draw) const {
  program_.use();
  view_uniforms_.set(view);
  set_color(color_, draw.style.color);
  glUniform1f(half_width_, 0.5f * draw.style.width_px);
  glUniform1f(dashed_, draw.style.dashed ? 1.0f : 0.0f);
  quads_.draw(draw.first, draw.count);
}

}  // namespace meshstep::render
