// A vertex array of TriangleVertex (shape_batches.hpp) in GPU memory, as shaders/fill.vert
// reads it: position at location 0, colour at location 1.
#pragma once

#include <cstddef>
#include <vector>

#include "gl_objects.hpp"
#include "shape_batches.hpp"

namespace meshstep::render {

class TriangleVertices {
 public:
  TriangleVertices() {
    vao_.bind();
    buffer_.bind();
    float_attribute(0, 2, sizeof(TriangleVertex), offsetof(TriangleVertex, position), false);
    color_attribute(1, sizeof(TriangleVertex), offsetof(TriangleVertex, color), false);
    glBindVertexArray(0);
  }
  void upload(const std::vector<TriangleVertex>& vertices) {
    buffer_.upload(vertices);
    triangles_ = vertices.size() / 3;
  }
  // Draws triangles [first, first + count): corner i of each is vertex 3 t + i, as the
  // shaders' gl_VertexID % 3 expects.
  void draw(std::size_t first, std::size_t count) const {
    vao_.bind();
    glDrawArrays(GL_TRIANGLES, static_cast<GLint>(3 * first), static_cast<GLsizei>(3 * count));
  }
  std::size_t triangles() const { return triangles_; }

 private:
  VertexArray vao_;
  ArrayBuffer buffer_;
  std::size_t triangles_ = 0;
};

}  // namespace meshstep::render
