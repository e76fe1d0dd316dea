// Writing a TIN: as a 3D surface (with an optional solid base), or as Triangle's files.
#pragma once

#include <optional>
#include <string>

#include "meshstep/io/surface_io.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"

namespace meshstep::app {

// Writes tin to path: Triangle's files when `format` is empty, else that surface format.
// base > 0 closes a surface into a solid that far below the lowest vertex.
void write_terrain(const std::string& path, const std::optional<io::SurfaceFormat>& format,
                   const terrain::HeightGrid& grid, const terrain::Tin& tin, double base);

}  // namespace meshstep::app
