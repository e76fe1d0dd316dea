// An ESRI ASCII grid as heights (meshstep/terrain/height_grid.hpp): the text is read by
// io::read_esri_grid_rows, row by row, straight into floats, which are kept whole or handed
// on (read_height_grid_rows, for tiles).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <span>
#include <system_error>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/huge_pages.hpp"
#include "meshstep/io/esri_grid.hpp"
#include "terrain/geographic.hpp"
#include "terrain/height_grid_readers.hpp"

namespace meshstep::terrain::detail {
namespace {

// Whether the file is long enough to hold `count` values (each takes a digit and a
// separator, but the last), so that room for them all can be made before they are read.
// A short file or a pipe is not trusted: the grid then grows with the values that arrive.
bool file_can_hold(const std::string& path, std::uint64_t count) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  const std::uint64_t bytes = std::filesystem::file_size(path, ec);
  return !ec && count <= (bytes + 1) / 2;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

// Sets dx, dy, geographic and units_note from the header and the user's choice.
void set_spacing(const std::string& path, const io::EsriGrid& header, const HeightGridOptions& options,
                 HeightGrid& grid) {
  const GridExtent extent{header.x0, header.y0, header.cellsize, header.ncols, header.nrows};
  const bool guessed = looks_geographic(extent);
  grid.geographic = options.geographic.value_or(guessed);
  if (!grid.geographic) {
    // Named at its line here; the terrain would refuse it too (planar_scale.hpp), unnamed.
    const double extent = static_cast<double>(std::max(header.ncols, header.nrows) - 1) * header.cellsize;
    if (!std::isfinite(extent))
      throw InputError(path, header.lines.cellsize,
                       "cellsize " + number(header.cellsize) + " over " +
                           std::to_string(std::max(header.ncols, header.nrows) - 1) +
                           " cells puts the grid's far side beyond the largest double (1.8e308)");
    grid.dx = grid.dy = header.cellsize;
    grid.units_note = number(header.cellsize) + " m cells (the grid's units, taken as metres)";
    if (guessed) grid.units_note += "; not converted from degrees, as told";
    return;
  }
  if (!latitudes_valid(extent))
    throw InputError(path, header.lines.y0,
                     "read as degrees, the grid spans latitudes " + number(extent.south) + " to " +
                         number(extent.north()) + ", beyond -90..90");
  const double latitude = extent.central_latitude();
  const GroundCells cells = degree_cells_in_metres(header.cellsize, latitude);
  grid.dx = cells.dx;
  grid.dy = cells.dy;
  grid.units_note = geographic_note(header.cellsize, latitude, cells);
  if (!options.geographic)
    grid.units_note += "; read as degrees: cells of at most 1 arc-minute within longitude -180..180, latitude -90..90";
}

}  // namespace

HeightGrid read_esri_height_rows(const std::string& path, const HeightGridOptions& options,
                                 const HeightRowVisitor& visit) {
  HeightGrid grid;
  std::vector<float> heights;
  std::size_t with_data = 0;
  const auto take_row = [&](const io::EsriGrid& header, std::size_t row, std::span<const double> values,
                            std::size_t line) {
    if (row == 0) {
      if (header.ncols < 2 || header.nrows < 2)
        throw InputError(path, header.ncols < 2 ? header.lines.ncols : header.lines.nrows,
                         too_few_samples(header.ncols, header.nrows));
      grid.nx = header.ncols;
      grid.ny = header.nrows;
      // The samples are the cells' centres.
      grid.x0 = header.x0 + header.cellsize / 2.0;
      grid.y0 = header.y0 + header.cellsize / 2.0;
      set_spacing(path, header, options, grid);
      heights.reserve(header.ncols);
    }
    heights.clear();
    for (const double v : values) {
      if (header.has_nodata && v == header.nodata) {
        heights.push_back(std::numeric_limits<float>::quiet_NaN());
        continue;
      }
      if (std::fabs(v) > FLT_MAX)
        throw InputError(path, line, "grid value " + number(v) + " is beyond the range of a float height (3.4e38)");
      heights.push_back(static_cast<float>(v));
      ++with_data;
    }
    visit(grid, grid.ny - 1 - row, heights);  // rows arrive northernmost first
  };
  const io::EsriGrid header = io::read_esri_grid_rows(path, take_row);
  if (with_data == 0)
    throw InputError(path, header.lines.nodata,
                     "every value is NODATA_value (" + number(header.nodata) + "): the grid has no data");
  return grid;
}

HeightGrid read_esri_height_grid(const std::string& path, const HeightGridOptions& options) {
  std::vector<float> z;
  HeightGrid grid = read_esri_height_rows(path, options, [&](const HeightGrid& header, std::size_t j,
                                                             std::span<const float> heights) {
    if (j == header.ny - 1) {
      const std::size_t count = header.nx * header.ny;
      if (file_can_hold(path, count)) reserve_huge(z, count);  // the one allocation
    }
    z.insert(z.end(), heights.begin(), heights.end());
  });
  grid.z = std::move(z);
  flip_rows(grid);
  return grid;
}

}  // namespace meshstep::terrain::detail
