// The readers behind read_surface (one per format, each in its read_surface_*.cpp) and what
// they share.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "meshstep/io/surface_io.hpp"

namespace meshstep::io::detail {

Surface read_off(const std::string& path);
Surface read_obj(const std::string& path);
Surface read_ply(const std::string& path);  // ASCII or binary, as its header says
Surface read_stl(const std::string& path);  // ASCII or binary, told apart by size and content

// Appends the polygon `corners` (at least 3) as the triangles (c0, ci, ci+1): a fan around
// its first corner. Exact for convex polygons, which is what exporters write, and each
// triangle keeps the polygon's orientation.
void add_fan(std::vector<std::array<std::uint32_t, 3>>& triangles,
             const std::vector<std::uint32_t>& corners);

// Binary formats have no lines: InputError(path, 0, "byte offset N: message").
[[noreturn]] void fail_at_byte(const std::string& path, std::uint64_t offset,
                               const std::string& message);

}  // namespace meshstep::io::detail
