// A GL driver library set up once per process: the EGL and OSMesa contexts share the work of
// opening it and looking its functions up.
#pragma once

#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "gl_context.hpp"

namespace meshstep::render {

// The Driver made from LIBRARY (Driver(library) opens it, throwing GlUnavailable, or
// std::runtime_error with dlopen's reason), made on first use and kept for the process. A
// failure is remembered and thrown again, prefixed with `backend` ("EGL: ..."), so a missing
// driver costs one dlopen however often it is asked for.
template <class Driver>
const Driver& driver_for(const std::string& library, const char* backend) {
  static std::mutex mutex;
  static std::unordered_map<std::string, std::unique_ptr<Driver>> drivers;
  static std::unordered_map<std::string, std::string> failures;
  const std::lock_guard lock(mutex);
  if (auto found = drivers.find(library); found != drivers.end()) return *found->second;
  if (auto failed = failures.find(library); failed != failures.end()) throw GlUnavailable(failed->second);
  try {
    return *drivers.emplace(library, std::make_unique<Driver>(library)).first->second;
  } catch (const GlUnavailable& e) {
    failures.emplace(library, e.what());
    throw;
  } catch (const std::runtime_error& e) {
    const std::string why = std::string(backend) + ": " + e.what();
    failures.emplace(library, why);
    throw GlUnavailable(why);
  }
}

}  // namespace meshstep::render
