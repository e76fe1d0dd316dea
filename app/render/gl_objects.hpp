// Owners of GL object names: each deletes its object when it goes (the context must be
// current then, as for every GL call).
#pragma once

#include <cstddef>

#include "gl.hpp"

namespace meshstep::render {

class VertexArray {
 public:
  VertexArray() { glGenVertexArrays(1, &name_); }
  ~VertexArray() { glDeleteVertexArrays(1, &name_); }
  VertexArray(const VertexArray&) = delete;
  VertexArray& operator=(const VertexArray&) = delete;
  void bind() const { glBindVertexArray(name_); }

 private:
  GLuint name_ = 0;
};

// An array buffer whose storage grows to the largest upload and is then reused.
class ArrayBuffer {
 public:
  ArrayBuffer() { glGenBuffers(1, &name_); }
  ~ArrayBuffer() { glDeleteBuffers(1, &name_); }
  ArrayBuffer(const ArrayBuffer&) = delete;
  ArrayBuffer& operator=(const ArrayBuffer&) = delete;

  void bind() const { glBindBuffer(GL_ARRAY_BUFFER, name_); }
  // Replaces the contents (binds the buffer).
  void upload(const void* data, std::size_t bytes) {
    bind();
    if (bytes > capacity_ || bytes < capacity_ / 4) {
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
      capacity_ = bytes;
    } else if (bytes > 0) {
      glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
    }
  }
  template <class Vector>
  void upload(const Vector& v) {
    upload(v.data(), v.size() * sizeof(v[0]));
  }

 private:
  GLuint name_ = 0;
  std::size_t capacity_ = 0;
};

class Texture {
 public:
  Texture() { glGenTextures(1, &name_); }
  ~Texture() { glDeleteTextures(1, &name_); }
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  void bind() const { glBindTexture(GL_TEXTURE_2D, name_); }
  GLuint name() const { return name_; }

 private:
  GLuint name_ = 0;
};

// A float vertex attribute read from the bound array buffer, `offset` bytes in; one value
// per vertex, or per instance when `per_instance`.
inline void float_attribute(GLuint location, int components, std::size_t stride, std::size_t offset,
                            bool per_instance) {
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(stride),
                        reinterpret_cast<const void*>(offset));
  glVertexAttribDivisor(location, per_instance ? 1 : 0);
}

// Four bytes read as a colour in 0..1.
inline void color_attribute(GLuint location, std::size_t stride, std::size_t offset, bool per_instance) {
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, 4, GL_UNSIGNED_BYTE, GL_TRUE, static_cast<GLsizei>(stride),
                        reinterpret_cast<const void*>(offset));
  glVertexAttribDivisor(location, per_instance ? 1 : 0);
}

}  // namespace meshstep::render
