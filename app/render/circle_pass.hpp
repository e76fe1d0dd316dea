// Circles with a world radius: an antialiased, optionally dashed ring and an optional fill
// (shaders/circle.vert, circle.frag).
#pragma once

#include <vector>

#include "instanced_quads.hpp"
#include "shader_program.hpp"
#include "shape_batches.hpp"
#include "view_uniforms.hpp"

namespace meshstep::render {

class CirclePass {
 public:
  CirclePass();
  void upload(const std::vector<CircleInstance>& circles) { quads_.upload(circles); }
  void draw(const View& view, const ShapeDraw& draw) const;

 private:
  ShaderProgram program_;
  ViewUniforms view_uniforms_;
  GLint color_, fill_, half_width_, dashed_;
  InstancedQuads<CircleInstance> quads_;
};

}  // namespace meshstep::render
