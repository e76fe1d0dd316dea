#include "painter.hpp"

#include "render/renderer.hpp"

namespace meshstep::app {

struct Painter::Impl {
  std::unique_ptr<render::GlContext> context;
  std::unique_ptr<render::Renderer> renderer;
};

Painter::Painter(const std::string& backend) : impl_(std::make_unique<Impl>()) {
  impl_->context = render::make_offscreen_context(backend);
  impl_->renderer = std::make_unique<render::Renderer>();
}

Painter::~Painter() {
  // The renderer's GL objects go while their context is still current.
  if (impl_ && impl_->context) impl_->context->make_current();
  impl_->renderer.reset();
}

void Painter::paint(const scene::Scene& scene, const scene::Camera& camera, int samples, scene::Image& image) {
  impl_->renderer->render(scene, camera, samples > 0 ? samples : render::kDefaultSamples);
  impl_->renderer->read_pixels(image);
}

std::string Painter::description() const {
  return std::string(impl_->context->name()) + ": " + impl_->context->describe();
}

}  // namespace meshstep::app
