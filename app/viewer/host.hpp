// Where the viewer's frames go: a GLFW window (people), or an off-screen framebuffer of
// EGL or OSMesa (scripts and tests on a machine with no display). Either way ImGui's draw
// data is drawn by ImGuiGl through meshstep's own GL loader, so both show the same pixels.
#pragma once

#include <memory>
#include <string>

#include "meshstep/scene/image.hpp"
#include "ui_look.hpp"

struct GLFWwindow;

namespace meshstep::viewer {

class Host {
 public:
  virtual ~Host() = default;
  // Starts a frame: reads the window's events (a window) and sets ImGui's display size and
  // frame time. False when the window was closed.
  virtual bool begin_frame(double seconds) = 0;
  // Draws ImGui's draw data and shows it; with `capture`, reads the frame into it first.
  virtual void end_frame(scene::Image* capture) = 0;
  virtual int width() const = 0;
  virtual int height() const = 0;
  // "GLFW window", "EGL (off screen)"...
  virtual std::string describe() const = 0;
  // The GL library a second context must come from to share the loaded GL functions (a
  // canvas worker's): "egl" (a window's GLX and EGL both go through libglvnd) or "osmesa".
  virtual std::string gl_library() const { return "egl"; }
  // True when ImGui's input comes from the window's events.
  virtual bool interactive() const = 0;
  // The last file dropped on the window since the last call ("" if none).
  virtual std::string take_dropped() { return {}; }
  // Uploads ImGui's font atlas again, after apply_ui_look (ui_look.hpp) rebuilt it.
  virtual void reload_fonts() = 0;
  // Full screen on the primary monitor, in its video mode, and back to the window's last
  // rectangle. False when it cannot be (off screen: there is no window; no monitor).
  virtual bool set_full_screen(bool on) { return !on; }
  virtual bool full_screen() const { return false; }
  // The window's size when not full screen (what the settings keep).
  virtual int windowed_width() const { return width(); }
  virtual int windowed_height() const { return height(); }
  // The window's title: what the window shows (a window shows it in its frame).
  virtual void set_title(const std::string& title) { title_ = title; }
  const std::string& title() const { return title_; }

 protected:
  std::string title_;
};

// Throws render::GlUnavailable when there is no display or no GL. The ImGui context must
// exist; the host loads the fonts' texture and (a window) the GLFW backend.
std::unique_ptr<Host> make_window_host(int width, int height, const std::string& title);
std::unique_ptr<Host> make_offscreen_host(int width, int height, const std::string& backend);

// The fonts and style every host uses: DejaVu Sans (embedded) at a size that reads at 720p,
// at the UI scale and for the theme of `look` (ui_look.hpp).
void setup_imgui_style(const UiLook& look = {});

}  // namespace meshstep::viewer
