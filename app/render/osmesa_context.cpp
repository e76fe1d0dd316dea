// The OSMesa context: Mesa's off-screen software renderer (llvmpipe), asked for an OpenGL 3.3
// core profile. OSMesa insists on a colour buffer of its own; it gets a one-pixel one, since
// the renderer draws into its own framebuffer object. libOSMesa is opened at run time; its
// header gives types and constants only (OSMesa was removed from Mesa in 25.1).
#include <array>
#include <cstdint>
#include <string>

#include <GL/osmesa.h>

#include "driver_cache.hpp"
#include "gl_context.hpp"
#include "shared_library.hpp"

#if defined(__SANITIZE_ADDRESS__)  // GCC
#define MESHSTEP_LEAK_CHECKED 1
#elif defined(__has_feature)  // Clang
#if __has_feature(address_sanitizer)
#define MESHSTEP_LEAK_CHECKED 1
#endif
#endif

#ifdef MESHSTEP_LEAK_CHECKED
// Mesa 22's OSMesa does not free what OSMesaMakeCurrent allocates for a context's buffers
// when the context is destroyed (LeakSanitizer finds about 200 bytes per context at exit).
// Those leaks would fail every sanitizer run of a program that made an OSMesa context; this
// tells LeakSanitizer they are the driver's. (A program may define this hook only once: add
// to this list rather than define another.)
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
#endif

namespace meshstep::render {

namespace {

using CreateContextAttribs = OSMesaContext (*)(const int* attributes, OSMesaContext share);
using MakeCurrent = GLboolean (*)(OSMesaContext, void* buffer, GLenum type, GLsizei width, GLsizei height);
using DestroyContext = void (*)(OSMesaContext);
using GetProcAddress = OSMESAproc (*)(const char* name);

struct OsmesaDriver {
  SharedLibrary library;
  CreateContextAttribs create_context = nullptr;
  MakeCurrent make_current = nullptr;
  DestroyContext destroy_context = nullptr;
  GetProcAddress get_proc_address = nullptr;

  explicit OsmesaDriver(const std::string& name) : library(name) {
    create_context = library.function<CreateContextAttribs>("OSMesaCreateContextAttribs");
    make_current = library.function<MakeCurrent>("OSMesaMakeCurrent");
    destroy_context = library.function<DestroyContext>("OSMesaDestroyContext");
    get_proc_address = library.function<GetProcAddress>("OSMesaGetProcAddress");
    if (!create_context || !make_current || !destroy_context || !get_proc_address)
      throw GlUnavailable("OSMesa: " + name + " lacks OSMesaCreateContextAttribs (Mesa 11.2 or later is needed)");
  }
};

class OsmesaContext final : public GlContext {
 public:
  explicit OsmesaContext(const OsmesaDriver& driver) : driver_(driver) {
    // No depth, stencil or accumulation buffers: the renderer needs none.
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 0,
                              OSMESA_STENCIL_BITS, 0,
                              OSMESA_ACCUM_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3,
                              0};
    context_ = driver_.create_context(attributes, nullptr);
    if (!context_) throw GlUnavailable("OSMesa: no OpenGL 3.3 core context");
  }

  ~OsmesaContext() override {
    // OSMesa has no way to release a context without binding another: destroying the
    // current one leaves nothing current, as intended.
    driver_.destroy_context(context_);
  }

  const char* name() const override { return "OSMesa"; }

 protected:
  void bind() override {
    if (!driver_.make_current(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw GlUnavailable("OSMesa: OSMesaMakeCurrent failed");
  }

  GlProc proc_address(const char* name) const override { return driver_.get_proc_address(name); }

 private:
  const OsmesaDriver& driver_;
  OSMesaContext context_ = nullptr;
  std::array<std::uint8_t, 4> pixel_{};  // the colour buffer OSMesa requires
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context(const std::string& library) {
  return std::make_unique<OsmesaContext>(driver_for<OsmesaDriver>(library, "OSMesa"));
}

}  // namespace meshstep::render
