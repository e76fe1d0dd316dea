// The readers behind read_height_grid, one per format (meshstep/terrain/height_grid.hpp).
#pragma once

#include <cstddef>
#include <string>

#include "meshstep/terrain/height_grid.hpp"

namespace meshstep::terrain::detail {

HeightGrid read_esri_height_grid(const std::string& path, const HeightGridOptions& options);
HeightGrid read_png_heightmap(const std::string& path, const HeightGridOptions& options);
// The ESRI grid row by row (read_height_grid_rows); the whole-grid reader is built on it.
HeightGrid read_esri_height_rows(const std::string& path, const HeightGridOptions& options,
                                 const HeightRowVisitor& visit);

// Every reader refuses a grid without triangles, in the same words.
inline std::string too_few_samples(std::size_t nx, std::size_t ny) {
  return std::to_string(nx) + " x " + std::to_string(ny) + " samples: a terrain needs at least 2 x 2 samples";
}

}  // namespace meshstep::terrain::detail
