// Thick, antialiased, optionally dashed line segments (shaders/line.vert, line.frag).
#pragma once

#include <vector>

#include "instanced_quads.hpp"
#include "shader_program.hpp"
#include "shape_batches.hpp"
#include "view_uniforms.hpp"

namespace meshstep::render {

class LinePass {
 public:
  LinePass();
  void upload(const std::vector<LineInstance>& lines) { quads_.upload(lines); }
  void draw(const View& view, const ShapeDraw& draw) const;

 private:
  ShaderProgram program_;
  ViewUniforms view_uniforms_;
  GLint color_, half_width_, dashed_;
  InstancedQuads<LineInstance> quads_;
};

}  // namespace meshstep::render
