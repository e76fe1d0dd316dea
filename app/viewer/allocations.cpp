// The allocation counter. meshstep-view's global operator new (count_new.cpp, linked
// into the program only) counts into it; the tests, which link the library alone, keep the
// standard operator new and count ImGui's allocations only.
#include "allocations.hpp"

#include <imgui.h>

#include <cstdlib>

namespace meshstep::viewer {

std::atomic<std::uint64_t> g_allocations{0};

namespace {

void* imgui_alloc(std::size_t size, void*) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size);
}

void imgui_free(void* p, void*) { std::free(p); }

}  // namespace

std::uint64_t allocations() { return g_allocations.load(std::memory_order_relaxed); }

void count_imgui_allocations() { ImGui::SetAllocatorFunctions(imgui_alloc, imgui_free, nullptr); }

}  // namespace meshstep::viewer
