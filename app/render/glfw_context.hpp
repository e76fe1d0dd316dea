// A GLFW window with an OpenGL 3.3 core context: the viewer's context. The renderer draws
// off-screen as always; Renderer::blit_to_default_framebuffer then copies its picture into
// the window before swap_buffers().
#pragma once

#include <memory>
#include <string>

#include "gl_context.hpp"

struct GLFWwindow;

namespace meshstep::render {

class GlfwContext final : public GlContext {
 public:
  // Opens the window (hidden unless `visible`). Throws GlUnavailable("GLFW: why"), e.g. when
  // there is no display.
  GlfwContext(int width, int height, const std::string& title, bool visible = true);
  ~GlfwContext() override;

  const char* name() const override { return "GLFW"; }
  GLFWwindow* window() const { return window_; }
  void swap_buffers();

 protected:
  void bind() override;
  GlProc proc_address(const char* name) const override;

 private:
  GLFWwindow* window_ = nullptr;
};

// A window context, already current.
std::unique_ptr<GlfwContext> make_window_context(int width, int height, const std::string& title,
                                                 bool visible = true);

}  // namespace meshstep::render
