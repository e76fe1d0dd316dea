// The drawing options `render` and `export` share: picture size, world window, what fills
// the triangles, which layers show, the theme, and which OpenGL context draws.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "meshstep/geometry/point.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/camera.hpp"

namespace meshstep::app {

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

// Throws CLI::ValidationError-like UsageError with a message naming the option.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
DrawSettings parse_draw_args(const DrawArgs& args);

}  // namespace meshstep::app
