// Which triangle, if any, an input segment passes through. Tells a segment that the
// triangulator failed to recover (it cuts through triangles) from one that legitimately
// has no mesh edges because it lies outside the meshed domain, in a hole or outside the
// outer boundary, where Triangle-style triangulators remove every triangle.
#pragma once

#include <cstdint>
#include <optional>

#include "check/stages.hpp"

namespace meshstep::check_detail {

// A good triangle whose interior the segment pq passes through by more than 1e-9 |pq|
// (the tolerance that admits rounded crossing points next to a segment's chain).
std::optional<std::uint32_t> crossed_triangle(MeshFacts& facts, const Point& p, const Point& q);

}  // namespace meshstep::check_detail
