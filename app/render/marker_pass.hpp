// Point markers of a fixed pixel size: disc, ring, square, cross, diamond
// (shaders/marker.vert, marker.frag).
#pragma once

#include <vector>

#include "instanced_quads.hpp"
#include "shader_program.hpp"
#include "shape_batches.hpp"
#include "view_uniforms.hpp"

namespace meshstep::render {

class MarkerPass {
 public:
  MarkerPass();
  void upload(const std::vector<MarkerInstance>& markers) { quads_.upload(markers); }
  void draw(const View& view, const ShapeDraw& draw) const;

 private:
  ShaderProgram program_;
  ViewUniforms view_uniforms_;
  GLint kind_, size_, half_width_, color_, fill_;
  InstancedQuads<MarkerInstance> quads_;
};

}  // namespace meshstep::render
