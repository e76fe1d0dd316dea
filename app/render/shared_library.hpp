// A shared library opened at run time (dlopen), for the GL drivers meshstep does not link.
#pragma once

#include <string>

namespace meshstep::render {

class SharedLibrary {
 public:
  // Opens NAME (a soname such as "libEGL.so.1", or a path). Throws std::runtime_error with
  // dlopen's reason. The library stays loaded until the process ends, even after this
  // object is gone: GL drivers keep thread-local state and exit handlers that must outlive
  // their last context, and unloading them is a known source of crashes at exit.
  explicit SharedLibrary(const std::string& name);

  // The address of the function NAME, or nullptr when the library has none.
  template <class Function>
  Function function(const char* name) const {
    return reinterpret_cast<Function>(symbol(name));
  }

  const std::string& name() const { return name_; }

 private:
  void* symbol(const char* name) const;
  std::string name_;
  void* handle_;
};

}  // namespace meshstep::render
