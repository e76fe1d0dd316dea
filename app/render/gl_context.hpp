// Where OpenGL comes from: a context behind one small interface, whatever made it.
//
// Three kinds exist: EGL surfaceless and OSMesa (off-screen, made here; their libraries are
// opened with dlopen at run time, so a machine without them still runs the rest of meshstep)
// and a GLFW window (glfw_context.hpp). Each gives the GL functions through its own
// getProcAddress; make_current() points the one glad loader of the program at them. Never
// call a gl* symbol of a linked libGL or libOSMesa by name: libGL and libOSMesa export the
// same names, and only the context's own functions reach the context.
//
// GL state is per thread and glad's function table per process: use one context at a time,
// from the thread that made it current; a second thread may draw with a context of the same
// GL library (make_current_with_loaded_functions).
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace meshstep::render {

// No OpenGL could be had; what() says why, for every backend that was tried.
class GlUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using GlProc = void (*)();

class GlContext {
 public:
  GlContext();
  virtual ~GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // "EGL", "OSMesa", "GLFW".
  virtual const char* name() const = 0;

  // Makes the context current on this thread and loads the GL functions from it (again only
  // when another context loaded them last). Throws GlUnavailable when it cannot, or when the
  // context lacks OpenGL 3.3.
  void make_current();

  // Makes the context current on this thread with the GL functions another context loaded:
  // a second context drawing on a worker thread while the first draws on its own. Both must
  // come from a GL library whose entry points dispatch on the calling thread's current
  // context: Mesa through libglvnd (a GLX window and EGL), or OSMesa with OSMesa. Throws
  // std::logic_error when no context loaded the functions yet, GlUnavailable when the
  // context cannot be made current.
  void make_current_with_loaded_functions();

  // "OpenGL 4.5 (Core Profile) Mesa 22.3.6 · llvmpipe (LLVM 15.0.6, 256 bits)"; the context
  // must be current.
  std::string describe() const;

 protected:
  // The platform's make-current; throws GlUnavailable on failure.
  virtual void bind() = 0;
  // The address of a GL function of this context (nullptr when it has none).
  virtual GlProc proc_address(const char* name) const = 0;

 private:
  static GlProc load_trampoline(void* self, const char* name);
  unsigned long serial_;  // tells contexts apart even when one reuses a dead one's address
};

enum class Backend { auto_, egl, osmesa };

// "auto", "egl", "osmesa".
const char* name(Backend backend);
std::optional<Backend> parse_backend(std::string_view text);

// An off-screen OpenGL 3.3 core context, already current. Backend::auto_ honours the
// environment variable MESHSTEP_GL (egl, osmesa or auto) and otherwise tries EGL, then
// OSMesa. Throws GlUnavailable saying why for each backend tried, e.g.
// "no OpenGL: EGL: libEGL.so.1: cannot open shared object file; OSMesa: ...".
std::unique_ptr<GlContext> make_offscreen_context(Backend backend = Backend::auto_);
// The same by name ("auto", "egl", "osmesa"); an unknown name throws GlUnavailable.
std::unique_ptr<GlContext> make_offscreen_context(std::string_view backend_name);

// The two off-screen kinds, made from a given library (a name for dlopen or a path), not yet
// current. Throw GlUnavailable("EGL: why") / GlUnavailable("OSMesa: why").
inline constexpr const char* kEglLibrary = "libEGL.so.1";
inline constexpr const char* kOsmesaLibrary = "libOSMesa.so.8";
std::unique_ptr<GlContext> make_egl_context(const std::string& library = kEglLibrary);
std::unique_ptr<GlContext> make_osmesa_context(const std::string& library = kOsmesaLibrary);
// An EGL context for a thread that draws beside another context (a viewer's canvas worker):
// on a display of the software device, whose rasterizer is its own (contexts of one display
// share theirs, and a big picture would hold up the other's small ones) and has one thread,
// leaving the other core to the first. Not yet current.
std::unique_ptr<GlContext> make_egl_worker_context(const std::string& library = kEglLibrary);

}  // namespace meshstep::render
