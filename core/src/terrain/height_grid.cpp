// What a height grid knows of its own samples (terrain/height_grid.hpp).
#include <algorithm>
#include <cmath>

#include "meshstep/error.hpp"
#include "meshstep/terrain/height_grid.hpp"

namespace meshstep::terrain {

std::pair<float, float> HeightGrid::height_range() const {
  float lo = INFINITY, hi = -INFINITY;
  for (const float h : z)
    if (!std::isnan(h)) {
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
  if (lo > hi) throw InputError("the height grid has no sample with data");
  return {lo, hi};
}

std::size_t HeightGrid::data_count() const {
  return static_cast<std::size_t>(std::count_if(z.begin(), z.end(), [](float h) { return !std::isnan(h); }));
}

}  // namespace meshstep::terrain
