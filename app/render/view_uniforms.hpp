// The uniforms every program shares (shaders/common.glsl): the picture's size and the map
// from local coordinates to its pixels.
#pragma once

#include "gl.hpp"
#include "meshstep/scene/scene.hpp"
#include "shader_program.hpp"
#include "world_frame.hpp"

namespace meshstep::render {

// Where the current frame draws: the picture's size, and local coordinates to its pixels.
struct View {
  int width = 1, height = 1;
  LocalToPixels to_pixels;
};

class ViewUniforms {
 public:
  // `with_transform`: false for programs that draw in pixels and have no u_scale/u_offset.
  explicit ViewUniforms(const ShaderProgram& program, bool with_transform = true)
      : viewport_(program.uniform("u_viewport")),
        scale_(with_transform ? program.uniform("u_scale") : -1),
        offset_(with_transform ? program.uniform("u_offset") : -1) {}

  // Sets them on the program in use.
  void set(const View& view) const {
    glUniform2f(viewport_, static_cast<float>(view.width), static_cast<float>(view.height));
    if (scale_ >= 0) glUniform2f(scale_, view.to_pixels.scale[0], view.to_pixels.scale[1]);
    if (offset_ >= 0) glUniform2f(offset_, view.to_pixels.offset[0], view.to_pixels.offset[1]);
  }

 private:
  GLint viewport_, scale_, offset_;
};

// A colour as the straight RGBA floats a shader's vec4 takes.
inline void set_color(GLint location, const scene::Rgba& c) {
  glUniform4f(location, c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, c.a / 255.0f);
}

}  // namespace meshstep::render
