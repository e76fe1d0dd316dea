// The regional attribute of each triangle of a moment of a run, found as the run's own
// output finds it: each region point in turn floods, from the triangle that holds it, every
// triangle it reaches without crossing a constrained edge, and a later region point
// overwrites an earlier one. A triangle no region point reaches gets 0, as Triangle writes.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "meshstep/pslg/pslg.hpp"

namespace meshstep::replay::detail {

// `constrained[t] >> i & 1`: triangle t's edge i, from its vertex i to vertex i + 1, is
// constrained (a replay FaceRecord's bits). For each triangle, 1 + the index of the region
// point whose flood reached it last, 0 when none did.
std::vector<std::uint32_t> region_of_triangles(std::span<const Point> points,
                                               std::span<const std::array<std::uint32_t, 3>> triangles,
                                               std::span<const std::uint8_t> constrained,
                                               std::span<const Region> regions);

// The same as regional attributes (0 where no region point reaches).
std::vector<double> region_attributes(std::span<const Point> points,
                                      std::span<const std::array<std::uint32_t, 3>> triangles,
                                      std::span<const std::uint8_t> constrained, std::span<const Region> regions);

}  // namespace meshstep::replay::detail
