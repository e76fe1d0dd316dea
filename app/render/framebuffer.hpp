// The renderer's own framebuffer: what it draws into whatever the context (a window's
// default framebuffer plays no part until blit_to_default). With samples > 1 drawing goes
// to a multisampled renderbuffer, resolved into a plain texture; with 1 sample it goes to
// the texture directly.
#pragma once

#include "gl.hpp"
#include "meshstep/scene/image.hpp"

namespace meshstep::render {

class Framebuffer {
 public:
  Framebuffer() = default;
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  // Makes it width x height with `samples` (clamped to 1..GL_MAX_SAMPLES); reallocates only
  // when something changed. Throws std::invalid_argument for a size GL cannot have.
  void resize(int width, int height, int samples);
  // Binds it for drawing, with the viewport on all of it.
  void bind_for_drawing() const;
  // Multisampled: averages the samples into the texture. Call after drawing.
  void resolve() const;

  // The resolved picture, rows top to bottom. Alpha is straight: the drawing is
  // premultiplied, and un-premultiplied here, unless the caller knows every pixel is opaque
  // (drawn over an opaque background).
  void read(scene::Image& image, bool opaque) const;
  // Copies the resolved picture into framebuffer 0 (a window), scaled to width x height.
  void blit_to_default(int width, int height) const;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  GLuint texture() const { return texture_; }

 private:
  void release();

  int width_ = 0, height_ = 0, samples_ = 0;
  GLuint resolved_fbo_ = 0, texture_ = 0;
  GLuint multisampled_fbo_ = 0, multisampled_color_ = 0;
};

}  // namespace meshstep::render
