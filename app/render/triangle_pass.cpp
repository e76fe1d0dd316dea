#include "triangle_pass.hpp"

namespace meshstep::render {

TrianglePass::TrianglePass()
    : program_("fill.vert", "fill.frag"), view_uniforms_(program_), smooth_edges_(program_.uniform("u_smooth_edges")) {}

void TrianglePass::draw(const View& view, const ShapeDraw& draw, bool multisampled) const {
  program_.use();
  view_uniforms_.set(view);
  glUniform1f(smooth_edges_, multisampled ? 0.0f : 1.0f);
  vertices_.draw(draw.first, draw.count);
}

}  // namespace meshstep::render
