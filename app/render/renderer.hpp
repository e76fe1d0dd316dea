// The OpenGL renderer of a scene (meshstep/scene/scene.hpp): draws it for a camera into its
// own framebuffer, from which the picture is read back or copied to a window.
//
//   auto context = make_offscreen_context();        // gl_context.hpp
//   Renderer renderer;                               // with the context current
//   renderer.render(scene, camera, kDefaultSamples);
//   scene::Image image = renderer.read_pixels();
//
// The layers draw in their order (scene.hpp), those switched off in scene.visible not at all.
// Everything is antialiased (thick lines, circles, markers and mesh edges by their distance
// fields, without glLineWidth); with samples > 1 the framebuffer is multisampled as well.
//
// Uploads follow changes: the mesh's buffers are filled again only when its points,
// triangles or colours change (a fingerprint of their contents tells), the shapes' only when
// the shapes change, and both when the camera moves so far that the float coordinates must
// be re-centred (world_frame.hpp). A camera change alone only changes uniforms.
//
// Shapes of the fill layer are drawn after the mesh's edges (fill and edges are one pass).
//
// A GL context must be current for every call, the destructor's included; it must be the
// same context for the life of the renderer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/image.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::render {

// Samples per pixel unless asked otherwise: 1. Every edge, stroke, circle, marker and glyph
// is antialiased in its shader, so 4x multisampling only smooths the outer rim of the fill
// (a 1280x720 frame of the teaching example differs from its 4x picture in 0.1-0.3% of the
// pixels, all along edges), while it costs half again the time of an exported animation and
// doubles that of a million triangles on llvmpipe.
inline constexpr int kDefaultSamples = 1;

// How the mesh is drawn. exact: every triangle by GL. approximate: the level of detail of
// mesh_raster.hpp, for a picture that must come fast (the viewer while the cursor moves): the
// triangles spanning a few pixels are found at the pixel centres on the CPU, the others drawn
// by GL. It is used only where it applies (one sample per pixel, the fill on and opaque, no
// painter's order), else the picture is exact anyway.
enum class Detail : std::uint8_t { exact, approximate };

class Renderer {
 public:
  // Compiles the shaders; throws std::runtime_error if they do not compile, std::logic_error
  // when no GL context was ever made current.
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws the scene as the camera sees it, at the camera's size, with `samples` samples per
  // pixel (1: none; clamped to what GL allows). Throws std::invalid_argument for a size GL
  // cannot have, std::runtime_error for a GL error.
  // `note`, when not empty, is written at the picture's bottom left over everything (the
  // viewer says so when a picture is approximate).
  void render(const scene::Scene& scene, const scene::Camera& camera, int samples = 1, Detail detail = Detail::exact,
              std::string_view note = {});

  // Whether Detail::approximate changes anything for this scene: one sample per pixel (the
  // raster finds one triangle per pixel), the fill on (it covers what it draws), triangles
  // in any order (not a 3D view's painter's order). Else the picture is exact anyway.
  static bool can_approximate(const scene::Scene& scene, int samples);

  // The last picture drawn, rows top to bottom.
  scene::Image read_pixels() const;
  // The same into an image whose memory is reused from frame to frame.
  void read_pixels(scene::Image& image) const;
  // Copies the last picture into framebuffer 0 (the current window's back buffer), scaled
  // to width x height pixels.
  void blit_to_default_framebuffer(int width, int height) const;

  // The GL texture holding the last picture (rows top to bottom), for a UI that shows it
  // as an image (the viewer's canvas). Valid until the next render.
  unsigned texture() const;

  // Forgets what was uploaded: the next render uploads everything again.
  void invalidate();

  // What the renderer did so far, for tests and benchmarks.
  struct Counters {
    std::size_t frames = 0;
    std::size_t mesh_uploads = 0;     // mesh buffers filled
    std::size_t overlay_uploads = 0;  // shape buffers filled
    std::size_t approximate_frames = 0;  // drawn with the level of detail
    std::size_t raster_triangles = 0;    // of the last such frame, drawn on the CPU
  };
  const Counters& counters() const;
  // The last picture's size and samples per pixel.
  int width() const;
  int height() const;
  int samples() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace meshstep::render
