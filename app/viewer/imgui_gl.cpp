#include "imgui_gl.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace meshstep::viewer {

ImGuiGl::ImGuiGl()
    : program_("imgui.vert", "imgui.frag"),
      window_(program_.uniform("u_window")),
      y_down_(program_.uniform("u_y_down")),
      texture_unit_(program_.uniform("u_texture")) {
  glGenBuffers(1, &vertices_);
  glGenBuffers(1, &indices_);
  vao_.bind();
  glBindBuffer(GL_ARRAY_BUFFER, vertices_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);  // recorded in the vertex array
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(ImDrawVert), reinterpret_cast<void*>(offsetof(ImDrawVert, pos)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(ImDrawVert), reinterpret_cast<void*>(offsetof(ImDrawVert, uv)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(ImDrawVert), reinterpret_cast<void*>(offsetof(ImDrawVert, col)));
  glBindVertexArray(0);
  glGenTextures(1, &font_);
  upload_fonts();
}

void ImGuiGl::upload_fonts() {
  ImGuiIO& io = ImGui::GetIO();
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  glBindTexture(GL_TEXTURE_2D, font_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  glBindTexture(GL_TEXTURE_2D, 0);
  io.Fonts->SetTexID(texture_id(font_));
}

ImGuiGl::~ImGuiGl() {
  glDeleteBuffers(1, &vertices_);
  glDeleteBuffers(1, &indices_);
  glDeleteTextures(1, &font_);
  ImGui::GetIO().Fonts->SetTexID(nullptr);
}

// Storage grows (doubling) and is then refilled in place: an idle viewer's frames then ask
// the driver for no memory (glBufferData reallocates every time).
void ImGuiGl::upload(GLenum target, const void* data, std::size_t bytes, std::size_t& capacity) {
  if (bytes > capacity) {
    capacity = std::max<std::size_t>(2 * capacity, bytes);
    glBufferData(target, static_cast<GLsizeiptr>(capacity), nullptr, GL_STREAM_DRAW);
  }
  glBufferSubData(target, 0, static_cast<GLsizeiptr>(bytes), data);
}

void ImGuiGl::draw(const ImDrawData& data, int width, int height, bool y_down) {
  if (width <= 0 || height <= 0) return;
  glViewport(0, 0, width, height);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_SCISSOR_TEST);
  program_.use();
  glUniform2f(window_, static_cast<float>(width), static_cast<float>(height));
  glUniform1f(y_down_, y_down ? 1.0f : -1.0f);
  glUniform1i(texture_unit_, 0);
  glActiveTexture(GL_TEXTURE0);
  vao_.bind();
  glBindBuffer(GL_ARRAY_BUFFER, vertices_);

  const ImVec2 origin = data.DisplayPos;
  for (int n = 0; n < data.CmdListsCount; ++n) {
    const ImDrawList& list = *data.CmdLists[n];
    upload(GL_ARRAY_BUFFER, list.VtxBuffer.Data, std::size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert), vertex_capacity_);
    upload(GL_ELEMENT_ARRAY_BUFFER, list.IdxBuffer.Data, std::size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx),
           index_capacity_);
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      if (cmd.UserCallback) {
        if (cmd.UserCallback != ImDrawCallback_ResetRenderState) cmd.UserCallback(&list, &cmd);
        continue;
      }
      const float x0 = cmd.ClipRect.x - origin.x, y0 = cmd.ClipRect.y - origin.y;
      const float x1 = cmd.ClipRect.z - origin.x, y1 = cmd.ClipRect.w - origin.y;
      if (x1 <= x0 || y1 <= y0) continue;
      // Scissor boxes count rows from the framebuffer's first row.
      const float row = y_down ? y0 : static_cast<float>(height) - y1;
      glScissor(static_cast<GLint>(x0), static_cast<GLint>(row), static_cast<GLsizei>(x1 - x0),
                static_cast<GLsizei>(y1 - y0));
      glBindTexture(GL_TEXTURE_2D, texture_name(cmd.GetTexID()));
      glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(cmd.ElemCount),
                               sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                               reinterpret_cast<void*>(static_cast<std::uintptr_t>(cmd.IdxOffset) * sizeof(ImDrawIdx)),
                               static_cast<GLint>(cmd.VtxOffset));
    }
  }
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void opaque_image(ImTextureID texture, ImVec2 size) {
  ImDrawList* list = ImGui::GetWindowDrawList();
  list->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
  ImGui::Image(texture, size);
  list->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glEnable(GL_BLEND); }, nullptr);
}

void opaque_image_at(ImDrawList& list, ImTextureID texture, ImVec2 p0, ImVec2 p1) {
  list.AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
  list.AddImage(texture, p0, p1);
  list.AddCallback([](const ImDrawList*, const ImDrawCmd*) { glEnable(GL_BLEND); }, nullptr);
}

}  // namespace meshstep::viewer
