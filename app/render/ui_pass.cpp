#include "ui_pass.hpp"

#include <cstddef>

namespace meshstep::render {

UiPass::UiPass()
    : program_("ui.vert", "ui.frag"),
      view_uniforms_(program_, false),
      atlas_(program_.uniform("u_atlas")),
      quads_({{0, 4, offsetof(UiQuad, rectangle)},
              {1, 4, offsetof(UiQuad, texture)},
              {2, 0, offsetof(UiQuad, top)},
              {3, 0, offsetof(UiQuad, bottom)}}) {}

void UiPass::draw(const View& view, const UiBatch& batch, scene::Layer layer) const {
  bool ready = false;
  for (const UiDraw& d : batch.draws()) {
    if (d.layer != layer) continue;
    if (!ready) {
      program_.use();
      view_uniforms_.set(view);
      glUniform1i(atlas_, 0);
      glActiveTexture(GL_TEXTURE0);
      ready = true;
    }
    glBindTexture(GL_TEXTURE_2D, d.texture);
    quads_.draw(d.first, d.count);
  }
}

}  // namespace meshstep::render
