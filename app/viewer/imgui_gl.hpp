// Draws Dear ImGui's draw data with meshstep's own GL loader (glad, fed by whichever context
// is current: a GLFW window, EGL or OSMesa). ImGui's stock OpenGL3 backend finds its
// functions through GLX and cannot start under OSMesa (STACK.md); this small renderer works
// in every context, so the scripted viewer draws the same UI off screen as in a window.
#pragma once

#include <imgui.h>

#include <cstddef>
#include <cstdint>

#include "render/gl.hpp"
#include "render/gl_objects.hpp"
#include "render/shader_program.hpp"

namespace meshstep::viewer {

class ImGuiGl {
 public:
  // Uploads the font atlas of the current ImGui context; a GL context must be current.
  ImGuiGl();
  ~ImGuiGl();
  ImGuiGl(const ImGuiGl&) = delete;
  ImGuiGl& operator=(const ImGuiGl&) = delete;

  // Draws into the bound framebuffer of width x height pixels. y_down: the framebuffer's
  // first row is the picture's top (an off-screen target read back as an image); false for
  // a window, whose first row is the bottom.
  void draw(const ImDrawData& data, int width, int height, bool y_down);
  // Uploads the current context's font atlas again (after apply_ui_look rebuilt it at
  // another size): the texture takes the atlas's new width and height.
  void upload_fonts();

 private:
  void upload(GLenum target, const void* data, std::size_t bytes, std::size_t& capacity);

  render::ShaderProgram program_;
  GLint window_, y_down_, texture_unit_;
  render::VertexArray vao_;
  GLuint vertices_ = 0, indices_ = 0, font_ = 0;
  std::size_t vertex_capacity_ = 0, index_capacity_ = 0;
};

// An image that covers what is under it (the canvas's picture), drawn without blending:
// on llvmpipe, blending the canvas's million pixels into the frame cost as much as the rest
// of the window together. The window under it should not draw a background either.
void opaque_image(ImTextureID texture, ImVec2 size);
// The same, into a draw list, over the rectangle from p0 to p1.
void opaque_image_at(ImDrawList& list, ImTextureID texture, ImVec2 p0, ImVec2 p1);

// A GL texture name as ImGui carries it, and back.
inline ImTextureID texture_id(GLuint name) { return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(name)); }
inline GLuint texture_name(ImTextureID id) { return static_cast<GLuint>(reinterpret_cast<std::uintptr_t>(id)); }

}  // namespace meshstep::viewer
