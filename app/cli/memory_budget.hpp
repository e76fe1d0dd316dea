// How much memory a refinement may take before it stops: --max-memory, or by default a
// quarter of the machine's. The budget becomes a triangle cap, so that a run stops at the
// same mesh on every machine given the same budget.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace meshstep::app {

// Peak resident memory per triangle of a refinement, measured: A.poly at 40 degrees to 4M
// triangles, 71 bytes; at 59 degrees to 63M, where almost every triangle waits in the queue,
// 130 bytes (8.2 GB); at 59 degrees with a 1 GB budget, 151 bytes. The larger, with room.
inline constexpr std::uint64_t kBytesPerTriangle = 160;

// "8G", "500M", "64K", "123456" (bytes; K, M, G, T are powers of 1024), "0" or "none" (no
// budget: 0). Empty when the text is none of these.
std::optional<std::uint64_t> parse_memory(const std::string& text);

// A quarter of the physical memory (4 GB when it cannot be read).
std::uint64_t default_memory_budget();

// "6.0 GB", "512 MB".
std::string memory_text(std::uint64_t bytes);

}  // namespace meshstep::app
