// How the program talks: errors and warnings on standard error, prefixed "meshstep:".
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include "meshstep/error.hpp"

namespace meshstep::app {

enum class Verbosity { quiet, normal, verbose };

inline void print_error(const std::string& message) {
  std::fprintf(stderr, "meshstep: error: %s\n", message.c_str());
}

// An input error's message, naming `input` when the error names no file itself.
inline std::string input_error_text(const std::string& input, const InputError& e) {
  return e.file().empty() ? input + ": " + e.what() : e.what();
}

inline void print_warning(Verbosity v, const std::string& message) {
  if (v != Verbosity::quiet) std::fprintf(stderr, "meshstep: warning: %s\n", message.c_str());
}

inline void print_progress(Verbosity v, const std::string& message) {
  if (v == Verbosity::verbose) {
    std::fprintf(stderr, "meshstep: %s\n", message.c_str());
    std::fflush(stderr);
  }
}

class Stopwatch {
 public:
  double lap_ms() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace meshstep::app
