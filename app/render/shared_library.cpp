#include "shared_library.hpp"

#include <dlfcn.h>

#include <stdexcept>

namespace meshstep::render {

SharedLibrary::SharedLibrary(const std::string& name) : name_(name) {
  // RTLD_LOCAL: the driver's gl* symbols must not become the process's (see gl_context.hpp).
  // RTLD_NODELETE: never unloaded, even by a later dlclose of another handle to it.
  handle_ = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (!handle_) {
    const char* why = dlerror();
    throw std::runtime_error(why ? why : name + ": cannot be opened");
  }
}

void* SharedLibrary::symbol(const char* name) const { return dlsym(handle_, name); }

}  // namespace meshstep::render
