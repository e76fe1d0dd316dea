// An input of issue 31's third hour-long fuzz of refine_options, shared by the CDT test and
// the refinement test of its fix (regressions/refine_options/vertex_beside_a_bent_piece_covered).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "meshstep/pslg/pslg.hpp"

namespace meshstep::testing {

// The segment (1,3)-(4,0) passes exactly through the input vertex (3,1) (index 5), and is
// crossed first by (41,3)-(1,2) at a point that rounds off its line; a hole at (2,2) is on
// one side of it, so its piece from the crossing to (4,0) is a boundary.
inline Pslg segment_through_a_vertex_bent_by_a_crossing() {
  Pslg in;
  in.points = {{0, 0}, {4, 0}, {41, 3}, {0, 8}, {1, 2}, {3, 1}, {3, 3}, {1, 3}};
  for (const auto& [a, b] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {0, 1}, {1, 2}, {2, 3}, {3, 0}, {2, 4}, {5, 3}, {6, 7}, {7, 1}})
    in.segments.push_back({a, b, 1});
  in.holes = {{2, 2}};
  return in;
}

}  // namespace meshstep::testing
