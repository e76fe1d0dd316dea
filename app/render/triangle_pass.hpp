// The overlays' filled triangles (highlighted faces, triangle shapes): usually translucent,
// smoothed at their edges when the framebuffer has no multisampling (shaders/fill.vert, fill.frag).
#pragma once

#include <vector>

#include "shader_program.hpp"
#include "shape_batches.hpp"
#include "triangle_vertices.hpp"
#include "view_uniforms.hpp"

namespace meshstep::render {

class TrianglePass {
 public:
  TrianglePass();
  void upload(const std::vector<TriangleVertex>& vertices) { vertices_.upload(vertices); }
  void draw(const View& view, const ShapeDraw& draw, bool multisampled) const;

 private:
  ShaderProgram program_;
  ViewUniforms view_uniforms_;
  GLint smooth_edges_;
  TriangleVertices vertices_;
};

}  // namespace meshstep::render
