#include "picture_texture.hpp"

namespace meshstep::viewer {

void PictureTexture::upload(const scene::Image& image) {
  current_ = (current_ + 1) % static_cast<int>(textures_.size());
  const auto at = static_cast<std::size_t>(current_);
  textures_[at].bind();
  std::array<int, 2>& size = sizes_[at];
  if (size[0] != image.width || size[1] != image.height) {
    // The canvas shows the picture at its own size, pixel for pixel: nearest is exact, and
    // cheaper than linear on llvmpipe.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    size = {image.width, image.height};
  } else {
    // Into the storage it has: no allocation on the UI thread.
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  }
}

}  // namespace meshstep::viewer
