// A picture drawn on another thread (the canvas's worker), shown as an ImGui image: three GL
// textures filled in turn. An upload never touches a texture that a frame still queued in
// the driver draws: llvmpipe would finish that frame first, and with the worker's picture
// of a million triangles holding the CPU that could take a second. The frame shown now is
// the only one in flight (a window's swap and the off-screen host's fence keep it so), so
// the texture uploaded into was last drawn two pictures ago.
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
