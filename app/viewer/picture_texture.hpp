// A picture drawn on another thread (the canvas's worker), shown as an ImGui image: three GL
// textures filled in turn. An upload never touches a texture that the frames still queued
// in the driver draw: llvmpipe would finish those frames first, and while the worker's
// picture of a million triangles holds the CPU that took up to a second. With two, the
// frames queued behind the worker still reached back to the older one (0.3-0.6 s uploads
// at 1e6); with three, the worst scrubbing frame is 40-70 ms.
#pragma once

#include <array>

#include <imgui.h>

#include "imgui_gl.hpp"
#include "meshstep/scene/image.hpp"
#include "render/gl_objects.hpp"

namespace meshstep::viewer {

class PictureTexture {
 public:
  // Needs the UI's GL context current, as every call does.
  void upload(const scene::Image& image);
  bool empty() const { return current_ < 0; }
  ImTextureID id() const { return texture_id(textures_[static_cast<std::size_t>(current_)].name()); }

 private:
  std::array<render::Texture, 3> textures_;
  std::array<std::array<int, 2>, 3> sizes_{};
  int current_ = -1;  // the one shown
};

}  // namespace meshstep::viewer
