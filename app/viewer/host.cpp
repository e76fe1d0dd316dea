#include "host.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "imgui_gl.hpp"
#include "render/framebuffer.hpp"
#include "render/gl_context.hpp"
#include "render/glfw_context.hpp"

namespace meshstep::viewer {

void setup_imgui_style(const UiLook& look) {
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the viewer keeps its own settings
  io.ConfigInputTextCursorBlink = false;
  apply_ui_look(look);
}

namespace {

// GLFW's drop callback takes no user pointer that ImGui's backend does not own already: the
// one window's last drop waits here.
std::string& dropped_path() {
  static std::string path;
  return path;
}

// A key pressed and released between two frames (a quick tap; xdotool's `key`) would never
// be seen down: ImGui 1.86 reads the keys' state once a frame. Its GLFW backend keeps a
// mouse button's press for a frame (MouseJustPressed); this does the same for keys: once a
// key was pressed since the frame began, every release waits for the next frame, in order.
// (Not only the pressed key's: a Ctrl+S tapped as Ctrl down in one frame, then S down, S
// up and Ctrl up in the next, must find Ctrl still down with S.)
struct KeyLatch {
  std::vector<int> pressed;               // since the last frame began
  std::vector<std::array<int, 3>> held;   // releases to make there: key, scancode, mods
};
KeyLatch& key_latch() {
  static KeyLatch latch;
  return latch;
}

void latched_key_callback(GLFWwindow* window, int key, int scancode, int action, int mods) {
  KeyLatch& latch = key_latch();
  if (action == GLFW_RELEASE && !latch.pressed.empty() && latch.held.size() < 64) {
    latch.held.push_back({key, scancode, mods});
    return;
  }
  if (action == GLFW_PRESS && latch.pressed.size() < 64) latch.pressed.push_back(key);
  ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
}

// Before the frame's events: the releases held back from the last frame, then a new frame.
void release_latched_keys(GLFWwindow* window) {
  KeyLatch& latch = key_latch();
  for (const auto& [key, scancode, mods] : latch.held) ImGui_ImplGlfw_KeyCallback(window, key, scancode, GLFW_RELEASE, mods);
  latch.held.clear();
  latch.pressed.clear();  // (capacity kept: an idle frame allocates nothing)
}

class WindowHost final : public Host {
 public:
  WindowHost(int width, int height, const std::string& title)
      : context_(render::make_window_context(width, height, title, true)) {
    ImGui_ImplGlfw_InitForOpenGL(context_->window(), true);
    key_latch().pressed.reserve(64);
    key_latch().held.reserve(64);
    glfwSetKeyCallback(context_->window(), latched_key_callback);  // ImGui's, through the latch
    // ImGui's backend leaves file drops alone: they are the viewer's.
    glfwSetDropCallback(context_->window(), [](GLFWwindow*, int count, const char** paths) {
      if (count > 0) dropped_path() = paths[count - 1];
    });
    gl_ = std::make_unique<ImGuiGl>();
  }
  ~WindowHost() override {
    context_->make_current();
    gl_.reset();
    ImGui_ImplGlfw_Shutdown();
  }

  bool begin_frame(double) override {
    release_latched_keys(context_->window());
    glfwPollEvents();
    if (glfwWindowShouldClose(context_->window())) return false;
    glfwGetFramebufferSize(context_->window(), &width_, &height_);
    ImGui_ImplGlfw_NewFrame();
    return true;
  }

  void end_frame(scene::Image* capture) override {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width_, height_);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (ImDrawData* data = ImGui::GetDrawData()) gl_->draw(*data, width_, height_, false);
    if (capture) read_back(*capture);
    context_->swap_buffers();
  }

  int width() const override { return width_; }
  int height() const override { return height_; }
  std::string describe() const override { return "GLFW window: " + context_->describe(); }
  bool interactive() const override { return true; }
  std::string take_dropped() override { return std::exchange(dropped_path(), std::string()); }
  void reload_fonts() override { gl_->upload_fonts(); }

  bool full_screen() const override { return glfwGetWindowMonitor(context_->window()) != nullptr; }
  bool set_full_screen(bool on) override {
    GLFWwindow* window = context_->window();
    if (on == full_screen()) return true;
    if (!on) {
      glfwSetWindowMonitor(window, nullptr, saved_[0], saved_[1], saved_[2], saved_[3], 0);
      return true;
    }
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (!mode) return false;
    // The rectangle to come back to.
    glfwGetWindowPos(window, &saved_[0], &saved_[1]);
    glfwGetWindowSize(window, &saved_[2], &saved_[3]);
    glfwSetWindowMonitor(window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
    return true;
  }
  int windowed_width() const override { return full_screen() ? saved_[2] : width_; }
  int windowed_height() const override { return full_screen() ? saved_[3] : height_; }

  void set_title(const std::string& title) override {
    if (title == title_) return;
    Host::set_title(title);
    glfwSetWindowTitle(context_->window(), title.c_str());
  }

 private:
  // The back buffer, bottom row first: flipped into an image's order.
  void read_back(scene::Image& image) const {
    image.width = width_;
    image.height = height_;
    image.rgba.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    const std::size_t row = static_cast<std::size_t>(width_) * 4;
    for (int y = 0; y < height_ / 2; ++y)
      std::swap_ranges(image.rgba.begin() + static_cast<std::ptrdiff_t>(y * row),
                       image.rgba.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                       image.rgba.begin() + static_cast<std::ptrdiff_t>((height_ - 1 - y) * row));
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  }

  std::unique_ptr<render::GlfwContext> context_;
  std::unique_ptr<ImGuiGl> gl_;
  int width_ = 0, height_ = 0;
  int saved_[4] = {0, 0, 0, 0};  // the window's x, y, width, height before full screen
};

class OffscreenHost final : public Host {
 public:
  OffscreenHost(int width, int height, const std::string& backend)
      : context_(render::make_offscreen_context(backend)), width_(width), height_(height) {
    target_.resize(width, height, 1);
    gl_ = std::make_unique<ImGuiGl>();
    // The keys ImGui's own widgets read (text fields, navigation), in GLFW's codes as in a
    // window, so scripts press the same keys everywhere.
    ImGuiIO& io = ImGui::GetIO();
    io.KeyMap[ImGuiKey_Tab] = GLFW_KEY_TAB;
    io.KeyMap[ImGuiKey_LeftArrow] = GLFW_KEY_LEFT;
    io.KeyMap[ImGuiKey_RightArrow] = GLFW_KEY_RIGHT;
    io.KeyMap[ImGuiKey_UpArrow] = GLFW_KEY_UP;
    io.KeyMap[ImGuiKey_DownArrow] = GLFW_KEY_DOWN;
    io.KeyMap[ImGuiKey_PageUp] = GLFW_KEY_PAGE_UP;
    io.KeyMap[ImGuiKey_PageDown] = GLFW_KEY_PAGE_DOWN;
    io.KeyMap[ImGuiKey_Home] = GLFW_KEY_HOME;
    io.KeyMap[ImGuiKey_End] = GLFW_KEY_END;
    io.KeyMap[ImGuiKey_Backspace] = GLFW_KEY_BACKSPACE;
    io.KeyMap[ImGuiKey_Enter] = GLFW_KEY_ENTER;
    io.KeyMap[ImGuiKey_Escape] = GLFW_KEY_ESCAPE;
  }
  ~OffscreenHost() override {
    context_->make_current();
    if (drawn_) glDeleteSync(drawn_);
    gl_.reset();
  }

  bool begin_frame(double seconds) override {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
    io.DeltaTime = static_cast<float>(seconds > 0.0 ? seconds : 1.0 / 30.0);
    return true;
  }

  void end_frame(scene::Image* capture) override {
    target_.bind_for_drawing();
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (ImDrawData* data = ImGui::GetDrawData()) gl_->draw(*data, width_, height_, true);
    if (capture) target_.read(*capture, true);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    present();
  }

  int width() const override { return width_; }
  int height() const override { return height_; }
  std::string describe() const override { return std::string(context_->name()) + " (off screen): " + context_->describe(); }
  bool interactive() const override { return false; }
  void reload_fonts() override { gl_->upload_fonts(); }
  std::string gl_library() const override { return context_->name() == std::string("OSMesa") ? "osmesa" : "egl"; }

 private:
  // What a window's swap does for its frames: hands this frame to the driver, and waits
  // until the one before it is drawn. Off screen nothing else would wait, and a script's
  // frames, made faster than llvmpipe draws them, would queue without bound; the first
  // texture upload that touched a queued frame then waited for the whole queue (a picture
  // from the canvas's worker: 0.2-0.6 s frames while scrubbing 1e5 points). One frame
  // stays in flight, as with double buffering, so making a frame and drawing the one
  // before overlap.
  void present() {
    const GLsync drawn = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glFlush();
    if (drawn_) {
      glClientWaitSync(drawn_, 0, GL_TIMEOUT_IGNORED);
      glDeleteSync(drawn_);
    }
    drawn_ = drawn;
  }

  std::unique_ptr<render::GlContext> context_;
  GLsync drawn_ = nullptr;  // the fence after the last frame
  render::Framebuffer target_;
  std::unique_ptr<ImGuiGl> gl_;
  int width_, height_;
};

}  // namespace

std::unique_ptr<Host> make_window_host(int width, int height, const std::string& title) {
  return std::make_unique<WindowHost>(width, height, title);
}

std::unique_ptr<Host> make_offscreen_host(int width, int height, const std::string& backend) {
  return std::make_unique<OffscreenHost>(width, height, backend);
}

}  // namespace meshstep::viewer
