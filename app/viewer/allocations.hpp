// How many times the viewer allocated: every C++ operator new and every ImGui allocation.
// meshstep-view's global operator new counts (count_new.cpp); a program without it counts
// ImGui's allocations only. OpenGL drivers allocate with malloc, outside this count.
#pragma once

#include <atomic>
#include <cstdint>

namespace meshstep::viewer {

extern std::atomic<std::uint64_t> g_allocations;

std::uint64_t allocations();

// Routes ImGui's allocations through the counter (call before ImGui::CreateContext).
void count_imgui_allocations();

}  // namespace meshstep::viewer
