// The drawing options `render` and `export` share: picture size, world window, what fills
// the triangles, which layers show, the theme, and which OpenGL context draws.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "command.hpp"
#include "console.hpp"
#include "meshstep/error.hpp"
#include "meshstep/geometry/point.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/camera.hpp"
#include "render/gl_context.hpp"

namespace meshstep::app {

// A bad option: the message names it.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct DrawArgs {
  std::string size = "1280x720";
  std::string view;  // "X0,Y0,X1,Y1"
  std::string color_by = "none";
  std::string layers;
  std::string theme = "light";
  std::string gl = "auto";
  int samples = 0;  // 0: chosen by the mesh's size
};

// Parsed and checked: what a picture needs besides the scene itself.
struct DrawSettings {
  int width = 1280, height = 720;
  std::optional<BBox> view;
  scene::SceneOptions scene;
  std::string gl = "auto";
  int samples = 0;

  // The camera for a scene whose content spans `bounds`: the --view window, else a fit.
  scene::Camera camera(const BBox& bounds) const;
};

void add_draw_options(CLI::App* cmd, DrawArgs& args);

DrawSettings parse_draw_args(const DrawArgs& args);

// Runs a picture command, turning its failures into a message and an exit status: usage
// errors 2; bad input, or no OpenGL to be had (with `gl_hint` appended), 1.
template <class F>
int with_picture_errors(const char* gl_hint, F&& f) {
  try {
    return f();
  } catch (const UsageError& e) {
    print_error(e.what());
    return kExitUsage;
  } catch (const InputError& e) {
    print_error(e.what());
    return kExitBadInput;
  } catch (const render::GlUnavailable& e) {
    print_error(std::string(e.what()) + gl_hint);
    return kExitBadInput;
  }
}

}  // namespace meshstep::app
