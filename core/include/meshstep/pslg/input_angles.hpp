// The smallest angle the input's segments make where they meet at a vertex: no mesh that
// keeps the segments can have all its angles above it there, whatever the algorithm, so
// refine warns before it starts when its angle bound is larger.
#pragma once

#include <cstdint>
#include <optional>

#include "meshstep/pslg/pslg.hpp"

namespace meshstep {

struct InputAngle {
  double degrees = 0.0;
  std::uint32_t vertex = 0;  // where the two segments meet (0-based)
  std::uint32_t first = 0, second = 0;  // the two segments (0-based)
};

// Segments of zero length, and a segment listed twice, are left out (the triangulation
// merges them), and so are corners of 180 degrees or more. Crossings away from vertices
// are not looked at. No angle: no two segments meet at less than 180 degrees.
std::optional<InputAngle> smallest_input_angle(const Pslg& in);

}  // namespace meshstep
