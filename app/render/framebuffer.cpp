#include "framebuffer.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace meshstep::render {

namespace {

void check_complete(const char* which) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string("the ") + which + " framebuffer is incomplete (status " +
                             std::to_string(status) + ")");
}

}  // namespace

Framebuffer::~Framebuffer() { release(); }

void Framebuffer::release() {
  glDeleteFramebuffers(1, &resolved_fbo_);
  glDeleteTextures(1, &texture_);
  glDeleteFramebuffers(1, &multisampled_fbo_);
  glDeleteRenderbuffers(1, &multisampled_color_);
  resolved_fbo_ = texture_ = multisampled_fbo_ = multisampled_color_ = 0;
  width_ = height_ = samples_ = 0;
}

void Framebuffer::resize(int width, int height, int samples) {
  GLint max_size = 0, max_samples = 1;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throw std::invalid_argument("cannot render a picture of " + std::to_string(width) + " x " +
                                std::to_string(height) + " pixels (1 to " + std::to_string(max_size) + ")");
  samples = std::clamp(samples, 1, std::max(1, max_samples));
  if (width == width_ && height == height_ && samples == samples_) return;
  release();
  width_ = width;
  height_ = height;
  samples_ = samples;

  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenFramebuffers(1, &resolved_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, resolved_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
  check_complete("resolved");

  if (samples > 1) {
    glGenRenderbuffers(1, &multisampled_color_);
    glBindRenderbuffer(GL_RENDERBUFFER, multisampled_color_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    glGenFramebuffers(1, &multisampled_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled_fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, multisampled_color_);
    check_complete("multisampled");
  }
}

void Framebuffer::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? multisampled_fbo_ : resolved_fbo_);
  glViewport(0, 0, width_, height_);
}

void Framebuffer::resolve() const {
  if (samples_ <= 1) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void Framebuffer::read(scene::Image& image, bool opaque) const {
  image.width = width_;
  image.height = height_;
  image.rgba.resize(static_cast<std::size_t>(width_) * 4 * static_cast<std::size_t>(height_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  // The framebuffer's first row is the picture's top (shaders/common.glsl): no flip.
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  if (opaque) return;
  // Un-premultiply the pixels that are not opaque.
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    const unsigned a = image.rgba[i + 3];
    if (a == 255) continue;
    for (int c = 0; c < 3; ++c)
      image.rgba[i + c] = a == 0 ? 0 : static_cast<std::uint8_t>(std::min(255u, (image.rgba[i + c] * 255u + a / 2) / a));
  }
}

void Framebuffer::blit_to_default(int width, int height) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  const bool same_size = width == width_ && height == height_;
  // Upside down: the picture's top row is the framebuffer's first, a window's is its last.
  glBlitFramebuffer(0, 0, width_, height_, 0, height, width, 0, GL_COLOR_BUFFER_BIT, same_size ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace meshstep::render
