#include "leak_check.hpp"

#include <atomic>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

namespace meshstep::render {

namespace {
std::atomic<bool> opted_in{false};
}

void check_leaks_before_gl_in_this_program() { opted_in = true; }

void check_leaks_now_if_gl_comes_next() {
#if defined(__SANITIZE_ADDRESS__)
  // Once per process: __lsan_do_leak_check reports (and exits non-zero on) a leak, and every
  // later call, including the one at exit, does nothing.
  if (opted_in.exchange(false)) __lsan_do_leak_check();
#endif
}

}  // namespace meshstep::render
