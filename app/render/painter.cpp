#include "render/painter.hpp"

#include "render/renderer.hpp"

namespace meshstep::render {

struct Painter::Impl {
  std::unique_ptr<GlContext> context;
  std::unique_ptr<Renderer> renderer;
};

Painter::Painter(const std::string& backend) : impl_(std::make_unique<Impl>()) {
  impl_->context = make_offscreen_context(backend);
  impl_->renderer = std::make_unique<Renderer>();
}

Painter::~Painter() {
  // The renderer's GL objects go while their context is still current.
  if (impl_ && impl_->context) impl_->context->make_current();
  impl_->renderer.reset();
}

void Painter::paint(const scene::Scene& scene, const scene::Camera& camera, int samples, scene::Image& image) {
  impl_->renderer->render(scene, camera, samples > 0 ? samples : kDefaultSamples);
  impl_->renderer->read_pixels(image);
}

std::string Painter::description() const {
  return std::string(impl_->context->name()) + ": " + impl_->context->describe();
}

}  // namespace meshstep::render
