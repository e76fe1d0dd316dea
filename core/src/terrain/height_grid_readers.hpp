// The readers behind read_height_grid, one per format (meshstep/terrain/height_grid.hpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>

#include "meshstep/terrain/height_grid.hpp"

namespace meshstep::terrain::detail {

HeightGrid read_esri_height_grid(const std::string& path, const HeightGridOptions& options);
HeightGrid read_png_heightmap(const std::string& path, const HeightGridOptions& options);
// The ESRI grid row by row (read_height_grid_rows); the whole-grid reader is built on it.
HeightGrid read_esri_height_rows(const std::string& path, const HeightGridOptions& options,
                                 const HeightRowVisitor& visit);

// GeoTIFF and the other rasters GDAL reads (read_gdal_height_grid.cpp); without GDAL
// (gdal_available() false) they refuse every file, saying what to install.
bool gdal_available();
HeightGrid read_gdal_height_grid(const std::string& path, const HeightGridOptions& options);
HeightGrid read_gdal_height_rows(const std::string& path, const HeightGridOptions& options,
                                 const HeightRowVisitor& visit);

// Readers whose rows arrive northernmost first: the grid keeps them southernmost first.
inline void flip_rows(HeightGrid& grid) {
  for (std::size_t j = 0, k = grid.ny - 1; j < k; ++j, --k)
    std::swap_ranges(grid.z.begin() + static_cast<std::ptrdiff_t>(j * grid.nx),
                     grid.z.begin() + static_cast<std::ptrdiff_t>((j + 1) * grid.nx),
                     grid.z.begin() + static_cast<std::ptrdiff_t>(k * grid.nx));
}

// Every reader refuses a grid without triangles, in the same words.
inline std::string too_few_samples(std::size_t nx, std::size_t ny) {
  return std::to_string(nx) + " x " + std::to_string(ny) + " samples: a terrain needs at least 2 x 2 samples";
}

}  // namespace meshstep::terrain::detail
