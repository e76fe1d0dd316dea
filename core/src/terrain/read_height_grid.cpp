// Choosing a height grid's reader by its file name (meshstep/terrain/height_grid.hpp), for
// the whole grid or row by row.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <span>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "terrain/height_grid_readers.hpp"

namespace meshstep::terrain {

namespace {

enum class GridFormat { esri, png, gdal };

// .asc and .png by their own readers; .tif, .tiff and, when meshstep has GDAL, any other
// name through GDAL (which knows some 200 raster formats, and says so when it does not).
GridFormat format_of(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".asc") return GridFormat::esri;
  if (extension == ".png") return GridFormat::png;
  if (extension == ".tif" || extension == ".tiff" || detail::gdal_available()) return GridFormat::gdal;
  throw InputError(path, 0,
                   "cannot tell the height grid's format from its name: expected .asc (ESRI ASCII grid), .png "
                   "(greyscale heightmap) or .tif (GeoTIFF, read through GDAL)");
}

}  // namespace

HeightGrid read_height_grid(const std::string& path, const HeightGridOptions& options) {
  switch (format_of(path)) {
    case GridFormat::esri: return detail::read_esri_height_grid(path, options);
    case GridFormat::gdal: return detail::read_gdal_height_grid(path, options);
    default: return detail::read_png_heightmap(path, options);
  }
}

HeightGrid read_height_grid_rows(const std::string& path, const HeightGridOptions& options,
                                 const HeightRowVisitor& visit) {
  if (format_of(path) == GridFormat::esri) return detail::read_esri_height_rows(path, options, visit);
  if (format_of(path) == GridFormat::gdal) return detail::read_gdal_height_rows(path, options, visit);
  HeightGrid grid = detail::read_png_heightmap(path, options);
  std::vector<float> whole = std::move(grid.z);
  grid.z = {};
  for (std::size_t j = grid.ny; j-- > 0;)
    visit(grid, j, std::span<const float>(whole).subspan(j * grid.nx, grid.nx));
  return grid;
}

}  // namespace meshstep::terrain
