// The EGL surfaceless context: Mesa's EGL_PLATFORM_SURFACELESS_MESA display, a configless
// OpenGL 3.3 core context and no surface at all (the renderer draws into its own
// framebuffer object). libEGL is opened at run time; its header gives types and constants.
#include <cstdlib>
#include <cstring>
#include <string>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "driver_cache.hpp"
#include "gl_context.hpp"
#include "shared_library.hpp"

namespace meshstep::render {

namespace {

const char* error_name(EGLint error) {
  switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    default: return "EGL error";
  }
}

// Whether the space-separated extension list names `extension` exactly.
bool has_extension(const char* list, const char* extension) {
  if (!list) return false;
  const std::size_t n = std::strlen(extension);
  for (const char* at = list; (at = std::strstr(at, extension)) != nullptr; at += n) {
    const bool starts = at == list || at[-1] == ' ';
    const bool ends = at[n] == ' ' || at[n] == '\0';
    if (starts && ends) return true;
  }
  return false;
}

// libEGL's entry points and the surfaceless display, set up once per library for the whole
// process. The display is never terminated: eglTerminate would end every context on it, and
// the platform display is one object shared by all of them.
struct EglDriver {
  SharedLibrary library;
  PFNEGLGETPROCADDRESSPROC get_proc_address = nullptr;
  PFNEGLGETERRORPROC get_error = nullptr;
  PFNEGLMAKECURRENTPROC make_current = nullptr;
  PFNEGLCREATECONTEXTPROC create_context = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroy_context = nullptr;
  PFNEGLGETCURRENTCONTEXTPROC current_context = nullptr;
  PFNEGLBINDAPIPROC bind_api = nullptr;
  EGLDisplay display = EGL_NO_DISPLAY;

  // The client API is per thread: desktop OpenGL must be chosen on the thread that creates
  // or binds a context, before it does.
  void use_desktop_gl() const {
    if (!bind_api(EGL_OPENGL_API))
      throw GlUnavailable(std::string("EGL: no desktop OpenGL (") + error_name(get_error()) + ")");
  }

  // Which display: Mesa's surfaceless platform display (one for the process), or a display
  // of the software device (EGL_EXT_platform_device) with a rasterizer of its own.
  enum class Display { surfaceless, own_device };

  explicit EglDriver(const std::string& name, Display which = Display::surfaceless) : library(name) {
    get_proc_address = library.function<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress");
    get_error = library.function<PFNEGLGETERRORPROC>("eglGetError");
    make_current = library.function<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");
    create_context = library.function<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
    destroy_context = library.function<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext");
    current_context = library.function<PFNEGLGETCURRENTCONTEXTPROC>("eglGetCurrentContext");
    const auto query_string = library.function<PFNEGLQUERYSTRINGPROC>("eglQueryString");
    const auto initialize = library.function<PFNEGLINITIALIZEPROC>("eglInitialize");
    bind_api = library.function<PFNEGLBINDAPIPROC>("eglBindAPI");
    if (!get_proc_address || !get_error || !make_current || !create_context || !destroy_context ||
        !current_context || !query_string || !initialize || !bind_api)
      throw GlUnavailable("EGL: " + name + " lacks EGL 1.4 functions");

    // Client extensions (EGL_NO_DISPLAY): the platform must be known before a display exists.
    const char* client = query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!has_extension(client, "EGL_EXT_platform_base") || !has_extension(client, "EGL_MESA_platform_surfaceless"))
      throw GlUnavailable("EGL: no surfaceless platform (EGL_MESA_platform_surfaceless)");
    const auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(get_proc_address("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) throw GlUnavailable("EGL: no eglGetPlatformDisplayEXT");
    if (which == Display::own_device) {
      display = software_device_display(client, get_platform_display);
      // Mesa's llvmpipe reads LP_NUM_THREADS when the display's screen is made (in
      // eglInitialize): one rasterizer thread leaves the other core to the UI's thread.
      const char* before = std::getenv("LP_NUM_THREADS");
      const std::string kept = before ? before : "";
      setenv("LP_NUM_THREADS", "1", 1);
      const bool ok = initialize(display, nullptr, nullptr);
      if (before) setenv("LP_NUM_THREADS", kept.c_str(), 1);
      else unsetenv("LP_NUM_THREADS");
      if (!ok) throw GlUnavailable(std::string("EGL: eglInitialize of the device failed (") + error_name(get_error()) + ")");
    } else {
      display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if (display == EGL_NO_DISPLAY)
        throw GlUnavailable(std::string("EGL: no surfaceless display (") + error_name(get_error()) + ")");
      if (!initialize(display, nullptr, nullptr))
        throw GlUnavailable(std::string("EGL: eglInitialize failed (") + error_name(get_error()) + ")");
    }

    const char* extensions = query_string(display, EGL_EXTENSIONS);
    if (!has_extension(extensions, "EGL_KHR_surfaceless_context"))
      throw GlUnavailable("EGL: no EGL_KHR_surfaceless_context");
    if (!has_extension(extensions, "EGL_KHR_no_config_context") &&
        !has_extension(extensions, "EGL_MESA_configless_context"))
      throw GlUnavailable("EGL: no configless contexts (EGL_KHR_no_config_context)");
    use_desktop_gl();
  }

  // The display of the software device (EGL_MESA_device_software), a display other than the
  // surfaceless platform's: Mesa gives each display its own screen and rasterizer threads.
  EGLDisplay software_device_display(const char* client, PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display) {
    if (!has_extension(client, "EGL_EXT_platform_device") || !has_extension(client, "EGL_EXT_device_enumeration"))
      throw GlUnavailable("EGL: no device platform (EGL_EXT_platform_device)");
    const auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(get_proc_address("eglQueryDevicesEXT"));
    const auto device_string =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(get_proc_address("eglQueryDeviceStringEXT"));
    if (!query_devices || !device_string) throw GlUnavailable("EGL: no eglQueryDevicesEXT");
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!query_devices(16, devices, &count)) count = 0;
    for (EGLint i = 0; i < count; ++i)
      if (has_extension(device_string(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software")) {
        const EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (d != EGL_NO_DISPLAY) return d;
      }
    throw GlUnavailable("EGL: no software device (EGL_MESA_device_software)");
  }
};

// The same on the software device's display.
struct EglWorkerDriver : EglDriver {
  explicit EglWorkerDriver(const std::string& name) : EglDriver(name, Display::own_device) {}
};

class EglContext final : public GlContext {
 public:
  explicit EglContext(const EglDriver& driver) : driver_(driver) {
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3,
                                 EGL_CONTEXT_MINOR_VERSION, 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    driver_.use_desktop_gl();
    context_ = driver_.create_context(driver_.display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT)
      throw GlUnavailable(std::string("EGL: no OpenGL 3.3 core context (") + error_name(driver_.get_error()) + ")");
  }

  ~EglContext() override {
    if (driver_.current_context() == context_)
      driver_.make_current(driver_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    driver_.destroy_context(driver_.display, context_);
  }

  const char* name() const override { return "EGL"; }

 protected:
  void bind() override {
    driver_.use_desktop_gl();
    if (!driver_.make_current(driver_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw GlUnavailable(std::string("EGL: eglMakeCurrent failed (") + error_name(driver_.get_error()) + ")");
  }

  GlProc proc_address(const char* name) const override { return driver_.get_proc_address(name); }

 private:
  const EglDriver& driver_;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> make_egl_context(const std::string& library) {
  return std::make_unique<EglContext>(driver_for<EglDriver>(library, "EGL"));
}

std::unique_ptr<GlContext> make_egl_worker_context(const std::string& library) {
  return std::make_unique<EglContext>(driver_for<EglWorkerDriver>(library, "EGL"));
}

}  // namespace meshstep::render
