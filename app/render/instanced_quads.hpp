// Per-instance data in GPU memory, drawn as one 4-vertex triangle strip per instance (the
// strip's corners come from gl_VertexID: shaders/common.glsl, strip_corner).
//
// OpenGL 3.3 has no base instance, so drawing a range [first, first + count) points the
// attributes at `first` before the draw: a handful of calls per shape, none per primitive.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "gl_objects.hpp"

namespace meshstep::render {

struct InstanceAttribute {
  GLuint location;
  int float_components;  // 0: a colour of 4 bytes
  std::size_t offset;
};

template <class Instance>
class InstancedQuads {
 public:
  explicit InstancedQuads(std::vector<InstanceAttribute> attributes) : attributes_(std::move(attributes)) {}

  void upload(const std::vector<Instance>& instances) { buffer_.upload(instances); }

  void draw(std::size_t first, std::size_t count) const {
    vao_.bind();
    buffer_.bind();
    for (const InstanceAttribute& a : attributes_) {
      const std::size_t offset = first * sizeof(Instance) + a.offset;
      if (a.float_components > 0)
        float_attribute(a.location, a.float_components, sizeof(Instance), offset, true);
      else
        color_attribute(a.location, sizeof(Instance), offset, true);
    }
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(count));
  }

 private:
  VertexArray vao_;
  ArrayBuffer buffer_;
  std::vector<InstanceAttribute> attributes_;
};

}  // namespace meshstep::render
