// Draws a UiBatch's items of one layer (shaders/ui.vert, ui.frag).
#pragma once

#include "instanced_quads.hpp"
#include "shader_program.hpp"
#include "ui_batch.hpp"
#include "view_uniforms.hpp"

namespace meshstep::render {

class UiPass {
 public:
  UiPass();
  void upload(const UiBatch& batch) { quads_.upload(batch.quads()); }
  // The batch must be the one last uploaded.
  void draw(const View& view, const UiBatch& batch, scene::Layer layer) const;

 private:
  ShaderProgram program_;
  ViewUniforms view_uniforms_;
  GLint atlas_;
  InstancedQuads<UiQuad> quads_;
};

}  // namespace meshstep::render
