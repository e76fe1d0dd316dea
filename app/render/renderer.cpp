#include "renderer.hpp"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "circle_pass.hpp"
#include "font_atlas.hpp"
#include "framebuffer.hpp"
#include "gl.hpp"
#include "meshstep/scene/layout.hpp"
#include "line_pass.hpp"
#include "marker_pass.hpp"
#include "mesh_pass.hpp"
#include "mesh_raster.hpp"
#include "overlay_text.hpp"
#include "scene_fingerprint.hpp"
#include "shape_batches.hpp"
#include "triangle_pass.hpp"
#include "ui_batch.hpp"
#include "ui_pass.hpp"
#include "world_frame.hpp"

namespace meshstep::render {

struct Renderer::State {
  MeshPass mesh;
  TrianglePass triangles;
  LinePass lines;
  CirclePass circles;
  MarkerPass markers;
  UiPass ui;
  FontCache fonts;
  Framebuffer target;

  MeshRaster raster;
  std::vector<std::uint32_t> raster_pixels, large_triangles;  // kept from frame to frame

  ShapeBatches shapes;
  UiBatch text;
  // What the buffers hold: the frame they were made in and the fingerprints of their inputs.
  std::optional<WorldFrame> frame;
  std::optional<std::uint64_t> mesh_fingerprint, overlay_fingerprint;
  bool opaque_background = true;  // of the last picture
  Counters counters;

  // Brings the buffers up to date with the scene and the camera; returns the frame to draw in.
  // `with_mesh`: false when the level of detail draws the mesh (its buffers are then left
  // as they are, to be filled at the next exact frame).
  WorldFrame upload(const scene::Scene& scene, const scene::Camera& camera, bool with_mesh);
  // The level of detail's mesh: the raster's image in place of the clear, the large
  // triangles into their buffers. Call with the target bound.
  void draw_approximate_mesh(const scene::Scene& scene, const WorldFrame& frame, const View& view);
  void draw_shapes(const View& view, scene::Layer layer) const;
};

WorldFrame Renderer::State::upload(const scene::Scene& scene, const scene::Camera& camera, bool with_mesh) {
  const WorldFrame chosen = choose_frame(scene.bounds, camera, frame ? &*frame : nullptr);
  const bool new_frame = frame != chosen;
  const std::uint64_t overlay_print = render::overlay_fingerprint(scene);
  if (with_mesh) {
    const std::uint64_t mesh_print = render::mesh_fingerprint(scene.mesh);
    if (new_frame || mesh_fingerprint != mesh_print) {
      mesh.upload(scene.mesh, chosen);
      ++counters.mesh_uploads;
    }
    mesh_fingerprint = mesh_print;
  } else if (new_frame) {
    mesh_fingerprint.reset();  // what the buffers hold is in the old frame
  }
  if (new_frame || overlay_fingerprint != overlay_print) {
    build_shape_batches(scene, chosen, shapes);
    triangles.upload(shapes.triangles);
    lines.upload(shapes.lines);
    circles.upload(shapes.circles);
    markers.upload(shapes.markers);
    ++counters.overlay_uploads;
  }
  frame = chosen;
  overlay_fingerprint = overlay_print;
  return chosen;
}

void Renderer::State::draw_approximate_mesh(const scene::Scene& scene, const WorldFrame& chosen, const View& view) {
  const scene::Rgba& bg = scene.background;
  // The background as glClear writes it (premultiplied, rounded to 8 bits).
  const auto channel = [&](std::uint8_t c) { return static_cast<std::uint32_t>(c * bg.a / 255.0f + 0.5f); };
  const std::uint32_t background = pack_rgba(channel(bg.r), channel(bg.g), channel(bg.b), bg.a);
  raster_pixels.assign(static_cast<std::size_t>(view.width) * static_cast<std::size_t>(view.height), background);
  const bool edges_on = scene.visible.has(scene::Layer::edges);
  raster.draw(scene.mesh, chosen, view, edges_on, raster_pixels, large_triangles);
  glBindTexture(GL_TEXTURE_2D, target.texture());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, view.width, view.height, GL_RGBA, GL_UNSIGNED_BYTE, raster_pixels.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  mesh.upload_subset(scene.mesh, chosen, large_triangles);
  mesh.draw_subset(view, scene.mesh, edges_on);
  ++counters.approximate_frames;
  counters.raster_triangles = raster.drawn();
}

void Renderer::State::draw_shapes(const View& view, scene::Layer layer) const {
  const bool multisampled = target.samples() > 1;
  for (const ShapeDraw& d : shapes.draws) {
    if (d.layer != layer) continue;
    switch (d.kind) {
      case scene::ShapeKind::triangles: triangles.draw(view, d, multisampled); break;
      case scene::ShapeKind::lines: lines.draw(view, d); break;
      case scene::ShapeKind::circles: circles.draw(view, d); break;
      case scene::ShapeKind::markers: markers.draw(view, d); break;
    }
  }
}

Renderer::Renderer() {
  // Before any context was made current the GL functions are not loaded, and the first GL
  // call would jump to address 0: say so instead.
  if (!GLAD_GL_VERSION_3_3)
    throw std::logic_error("Renderer: no OpenGL functions loaded: make a context current first (GlContext)");
  state_ = std::make_unique<State>();
}

Renderer::~Renderer() = default;

void Renderer::render(const scene::Scene& scene, const scene::Camera& camera, int samples, Detail detail,
                      std::string_view note) {
  State& s = *state_;
  s.target.resize(camera.width(), camera.height(), samples);
  const bool approximate = detail == Detail::approximate && can_approximate(scene, s.target.samples());
  const WorldFrame frame = s.upload(scene, camera, !approximate);
  const View view{camera.width(), camera.height(), local_to_pixels(frame, camera)};

  // The words depend on the camera (labels follow their points): laid out every frame.
  s.fonts.begin_frame();
  s.text.clear();
  // (scene::layout leaves out the caption and the legend when their layers are off.)
  const scene::Layout layout = scene::layout(scene, camera.width(), camera.height());
  if (scene.visible.has(scene::Layer::labels)) add_labels(scene, camera, s.fonts, s.text);
  add_caption(scene, layout, s.fonts, s.text);
  add_legend(scene, layout, s.fonts, s.text);
  add_narration(scene, layout, s.fonts, s.text);
  add_note(scene, camera.height(), note, s.fonts, s.text);
  s.ui.upload(s.text);

  s.target.bind_for_drawing();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied colour (shaders/common.glsl)
  const scene::Rgba& bg = scene.background;
  s.opaque_background = bg.a == 255;
  const float alpha = bg.a / 255.0f;
  glClearColor(bg.r / 255.0f * alpha, bg.g / 255.0f * alpha, bg.b / 255.0f * alpha, alpha);
  if (approximate)
    s.draw_approximate_mesh(scene, frame, view);  // the clear and the mesh in one
  else
    glClear(GL_COLOR_BUFFER_BIT);

  for (std::size_t i = 0; i < scene::kLayerCount; ++i) {
    const auto layer = static_cast<scene::Layer>(i);
    // Fill and edges are one pass, drawn at the fill's turn (edges come right after it).
    if (layer == scene::Layer::fill && !approximate)
      s.mesh.draw(view, scene.mesh, scene.visible.has(scene::Layer::fill), scene.visible.has(scene::Layer::edges));
    if (!scene.visible.has(layer)) continue;
    s.draw_shapes(view, layer);
    s.ui.draw(view, s.text, layer);
  }
  if (!note.empty() || !scene.narration.empty()) s.ui.draw(view, s.text, kNoteLayer);
  s.target.resolve();
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ++s.counters.frames;

  if (const GLenum error = glGetError(); error != GL_NO_ERROR)
    throw std::runtime_error("OpenGL error " + std::to_string(error) + " while rendering");
}

bool Renderer::can_approximate(const scene::Scene& scene, int samples) {
  return samples == 1 && scene.visible.has(scene::Layer::fill) && !scene.mesh.painter_order &&
         !scene.mesh.triangles.empty();
}

scene::Image Renderer::read_pixels() const {
  scene::Image image;
  read_pixels(image);
  return image;
}

void Renderer::read_pixels(scene::Image& image) const {
  state_->target.read(image, state_->opaque_background);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::blit_to_default_framebuffer(int width, int height) const { state_->target.blit_to_default(width, height); }

void Renderer::invalidate() {
  state_->frame.reset();
  state_->mesh_fingerprint.reset();
  state_->overlay_fingerprint.reset();
}

const Renderer::Counters& Renderer::counters() const { return state_->counters; }
unsigned Renderer::texture() const { return state_->target.texture(); }
int Renderer::width() const { return state_->target.width(); }
int Renderer::height() const { return state_->target.height(); }
int Renderer::samples() const { return state_->target.samples(); }

}  // namespace meshstep::render
