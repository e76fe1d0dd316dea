// Pictures of scenes as pixels, drawn by the OpenGL renderer in an off-screen context
// (EGL surfaceless or OSMesa), for the commands that write PNGs and for the Python module's
// RGB arrays. Where no OpenGL can be had, opening one throws GlUnavailable saying why; SVG
// needs none of this.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/image.hpp"
#include "meshstep/scene/scene.hpp"
#include "render/gl_context.hpp"

namespace meshstep::render {

class Painter {
 public:
  // backend: "auto", "egl" or "osmesa" (MESHSTEP_GL overrides "auto").
  explicit Painter(const std::string& backend);
  ~Painter();
  Painter(const Painter&) = delete;
  Painter& operator=(const Painter&) = delete;

  // samples 0: render::kDefaultSamples. The image's memory is reused from call to call
  // when the caller hands the same one back.
  void paint(const scene::Scene& scene, const scene::Camera& camera, int samples, scene::Image& image);
  scene::Image paint(const scene::Scene& scene, const scene::Camera& camera, int samples) {
    scene::Image image;
    paint(scene, camera, samples, image);
    return image;
  }
  // "EGL: OpenGL 4.5 (Core Profile) Mesa 22.3.6 · llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string description() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace meshstep::render
