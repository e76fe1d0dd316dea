#include "shader_program.hpp"

#include <stdexcept>
#include <string>

#include "embedded_files.hpp"

namespace meshstep::render {

namespace {

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  is_program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  is_program ? glGetProgramInfoLog(object, length, nullptr, log.data())
             : glGetShaderInfoLog(object, length, nullptr, log.data());
  return log.c_str();
}

GLuint compile(GLenum stage, std::string_view file) {
  const bool vertex = stage == GL_VERTEX_SHADER;
  // "#line 1" after the common part: the compiler's line numbers are the file's own.
  const std::string source = std::string("#version 330 core\n") +
                             (vertex ? "#define MESHSTEP_VERTEX_SHADER\n" : "#define MESHSTEP_FRAGMENT_SHADER\n") +
                             std::string(embedded_file("common.glsl")) + "\n#line 1\n" +
                             std::string(embedded_file(file));
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(shader, false);
    glDeleteShader(shader);
    throw std::runtime_error(std::string(file) + " does not compile:\n" + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(std::string_view vertex_file, std::string_view fragment_file) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_file);
  GLuint fragment = 0;
  try {
    fragment = compile(GL_FRAGMENT_SHADER, fragment_file);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glBindFragDataLocation(program_, 0, "fragment");
  glLinkProgram(program_);
  // The program keeps what it needs; the shader objects go when it does.
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(program_, true);
    glDeleteProgram(program_);
    throw std::runtime_error(std::string(vertex_file) + " + " + std::string(fragment_file) + " do not link:\n" + log);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(program_); }

GLint ShaderProgram::uniform(const char* name) const {
  const GLint location = glGetUniformLocation(program_, name);
  if (location < 0) throw std::logic_error(std::string("shader program has no uniform ") + name);
  return location;
}

}  // namespace meshstep::render
