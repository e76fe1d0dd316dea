// A linked GLSL program made from two embedded shader files (shaders/*.vert, *.frag), each
// compiled with shaders/common.glsl in front.
#pragma once

#include <string_view>

#include "gl.hpp"

namespace meshstep::render {

class ShaderProgram {
 public:
  // Compiles and links; throws std::runtime_error with the compiler's log, naming the file.
  ShaderProgram(std::string_view vertex_file, std::string_view fragment_file);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const { glUseProgram(program_); }
  // The location of a uniform the program must have (throws std::logic_error otherwise: a
  // misspelt or optimised-away uniform is a bug to see at once, not a silent no-op).
  GLint uniform(const char* name) const;

 private:
  GLuint program_ = 0;
};

}  // namespace meshstep::render
