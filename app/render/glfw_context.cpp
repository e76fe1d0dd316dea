#include "glfw_context.hpp"

#include <mutex>

#define GLFW_INCLUDE_NONE  // glad provides the GL declarations, not GLFW
#include <GLFW/glfw3.h>

namespace meshstep::render {

namespace {

// GLFW is initialised once for the process and stays so: glfwTerminate would destroy every
// window, and the viewer may open more than one over its life.
void initialise_glfw() {
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] {
    if (!glfwInit()) {
      const char* why = nullptr;
      glfwGetError(&why);
      failure = std::string("GLFW: ") + (why ? why : "glfwInit failed");
    }
  });
  if (!failure.empty()) throw GlUnavailable(failure);
}

}  // namespace

GlfwContext::GlfwContext(int width, int height, const std::string& title, bool visible) {
  initialise_glfw();
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  // The renderer antialiases in its own framebuffer; the window's needs no samples.
  glfwWindowHint(GLFW_SAMPLES, 0);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const char* why = nullptr;
    glfwGetError(&why);
    throw GlUnavailable(std::string("GLFW: ") + (why ? why : "no window"));
  }
}

GlfwContext::~GlfwContext() {
  if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
  glfwDestroyWindow(window_);
}

void GlfwContext::swap_buffers() { glfwSwapBuffers(window_); }

void GlfwContext::bind() { glfwMakeContextCurrent(window_); }

GlProc GlfwContext::proc_address(const char* name) const { return glfwGetProcAddress(name); }

std::unique_ptr<GlfwContext> make_window_context(int width, int height, const std::string& title, bool visible) {
  auto context = std::make_unique<GlfwContext>(width, height, title, visible);
  context->make_current();
  return context;
}

}  // namespace meshstep::render
