#include "gl_context.hpp"

#include <atomic>
#include <cstdlib>
#include <stdexcept>

#include "gl.hpp"
#include "leak_check.hpp"

namespace meshstep::render {

namespace {

std::atomic<unsigned long> next_serial{1};
// The context whose functions fill glad's table (0: none yet).
std::atomic<unsigned long> loaded_serial{0};

std::string text_of(GLenum what) {
  const auto* text = reinterpret_cast<const char*>(glGetString(what));
  return text ? text : "?";
}

}  // namespace

GlContext::GlContext() : serial_(next_serial++) { check_leaks_now_if_gl_comes_next(); }

GlProc GlContext::load_trampoline(void* self, const char* name) {
  return static_cast<const GlContext*>(self)->proc_address(name);
}

void GlContext::make_current() {
  bind();
  if (loaded_serial == serial_) return;
  loaded_serial = 0;
  const int version = gladLoadGLUserPtr(&GlContext::load_trampoline, this);
  if (version == 0) throw GlUnavailable(std::string(name()) + ": the GL functions could not be loaded");
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
    throw GlUnavailable(std::string(name()) + ": OpenGL " + std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                        std::to_string(GLAD_VERSION_MINOR(version)) + ", 3.3 core is needed");
  loaded_serial = serial_;
}

void GlContext::make_current_with_loaded_functions() {
  if (loaded_serial == 0) throw std::logic_error("no GL context has loaded the GL functions yet");
  bind();
}

std::string GlContext::describe() const {
  return "OpenGL " + text_of(GL_VERSION) + " \u00b7 " + text_of(GL_RENDERER);
}

const char* name(Backend backend) {
  switch (backend) {
    case Backend::auto_: return "auto";
    case Backend::egl: return "egl";
    case Backend::osmesa: return "osmesa";
  }
  return "unknown";
}

std::optional<Backend> parse_backend(std::string_view text) {
  for (Backend b : {Backend::auto_, Backend::egl, Backend::osmesa})
    if (text == name(b)) return b;
  return std::nullopt;
}

namespace {

// The context of one backend, current; or nullptr with the reason appended to `why`.
std::unique_ptr<GlContext> try_backend(Backend backend, std::string& why) {
  try {
    std::unique_ptr<GlContext> context = backend == Backend::egl ? make_egl_context() : make_osmesa_context();
    context->make_current();
    return context;
  } catch (const GlUnavailable& e) {
    why += e.what();
  }
  return nullptr;
}

}  // namespace

std::unique_ptr<GlContext> make_offscreen_context(Backend backend) {
  std::string why = "no OpenGL: ";
  if (backend == Backend::auto_) {
    if (const char* chosen = std::getenv("MESHSTEP_GL"); chosen && *chosen) {
      const std::optional<Backend> parsed = parse_backend(chosen);
      if (!parsed) throw GlUnavailable(why + "MESHSTEP_GL=" + chosen + " names no backend (auto, egl or osmesa)");
      backend = *parsed;
    }
  }
  switch (backend) {
    case Backend::egl:
    case Backend::osmesa:
      if (auto context = try_backend(backend, why)) return context;
      throw GlUnavailable(why);
    case Backend::auto_:
      if (auto context = try_backend(Backend::egl, why)) return context;
      why += "; ";
      if (auto context = try_backend(Backend::osmesa, why)) return context;
      throw GlUnavailable(why);
  }
  throw GlUnavailable(why + "backend number " + std::to_string(static_cast<int>(backend)) +
                      " does not exist (auto, egl or osmesa)");
}

std::unique_ptr<GlContext> make_offscreen_context(std::string_view backend_name) {
  const std::optional<Backend> backend = parse_backend(backend_name);
  if (!backend)
    throw GlUnavailable("no OpenGL: '" + std::string(backend_name) + "' names no backend (auto, egl or osmesa)");
  return make_offscreen_context(*backend);
}

}  // namespace meshstep::render
