#include "plain_frame.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "render/gl.hpp"

namespace meshstep::bench {

namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 a_position;  // clip coordinates
layout(location = 1) in vec4 a_color;
flat out vec4 v_color;
void main() { v_color = a_color; gl_Position = vec4(a_position, 0.0, 1.0); }
)";

constexpr const char* kFragmentShader = R"(#version 330 core
flat in vec4 v_color;
out vec4 fragment;
void main() { fragment = v_color; }
)";

GLuint compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) throw std::runtime_error("plain_frame: a shader did not compile");
  return shader;
}

struct Corner {
  float x, y;
  std::uint32_t rgba;
};

}  // namespace

struct PlainFrame::Gl {
  GLuint program = 0, vao = 0, buffer = 0, framebuffer = 0, texture = 0;
  ~Gl() {
    glDeleteProgram(program);
    glDeleteVertexArrays(1, &vao);
    glDeleteBuffers(1, &buffer);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
  }
};

PlainFrame::PlainFrame(const TriMesh& mesh, int width, int height)
    : gl_(std::make_unique<Gl>()), width_(width), height_(height) {
  // Fit the mesh's bounding box into clip space (the renderer fits it with margins; the
  // difference in covered pixels is a few percent).
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Point& p : mesh.points) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const double scale = 1.9 / std::max({x1 - x0, y1 - y0, 1e-300});
  std::vector<Corner> corners;
  corners.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t colour = 0xff000000u | (static_cast<std::uint32_t>(t * 2654435761u) & 0xffffffu);
    for (const auto v : mesh.triangles[t]) {
      const Point& p = mesh.points[v];
      corners.push_back({float((p.x - x0) * scale - 0.95), float((p.y - y0) * scale - 0.95), colour});
    }
  }
  vertex_count_ = corners.size();

  gl_->program = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader), fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  glAttachShader(gl_->program, vs);
  glAttachShader(gl_->program, fs);
  glLinkProgram(gl_->program);
  glDeleteShader(vs);
  glDeleteShader(fs);

  glGenVertexArrays(1, &gl_->vao);
  glBindVertexArray(gl_->vao);
  glGenBuffers(1, &gl_->buffer);
  glBindBuffer(GL_ARRAY_BUFFER, gl_->buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners.size() * sizeof(Corner)), corners.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Corner), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Corner), reinterpret_cast<void*>(offsetof(Corner, rgba)));
  glBindVertexArray(0);

  glGenTextures(1, &gl_->texture);
  glBindTexture(GL_TEXTURE_2D, gl_->texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGenFramebuffers(1, &gl_->framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, gl_->framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, gl_->texture, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  pixels_.resize(static_cast<std::size_t>(width) * height * 4);
}

PlainFrame::~PlainFrame() = default;

void PlainFrame::draw_and_read() {
  glBindFramebuffer(GL_FRAMEBUFFER, gl_->framebuffer);
  glViewport(0, 0, width_, height_);
  glDisable(GL_BLEND);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(gl_->program);
  glBindVertexArray(gl_->vao);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertex_count_));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels_.data());
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glEnable(GL_BLEND);
}

}  // namespace meshstep::bench
