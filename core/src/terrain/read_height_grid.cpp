// Choosing a height grid's reader by its file name (meshstep/terrain/height_grid.hpp).
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "meshstep/error.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "terrain/height_grid_readers.hpp"

namespace meshstep::terrain {

HeightGrid read_height_grid(const std::string& path, const HeightGridOptions& options) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".asc") return detail::read_esri_height_grid(path, options);
  if (extension == ".png") return detail::read_png_heightmap(path, options);
  throw InputError(path, 0,
                   "cannot tell the height grid's format from its name: expected .asc (ESRI ASCII grid) or .png "
                   "(greyscale heightmap)");
}

}  // namespace meshstep::terrain
