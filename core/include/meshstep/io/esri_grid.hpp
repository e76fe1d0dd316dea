// ESRI ASCII grids (.asc): a raster of values over a rectangle, used as a size function
// (`meshstep refine --size GRID.asc`) and, later, as terrain heights.
//
//   ncols N / nrows M / xllcorner X (or xllcenter) / yllcorner Y (or yllcenter) /
//   cellsize C / [NODATA_value V] / then M rows of N values, the first row the northernmost.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "meshstep/geometry/point.hpp"

namespace meshstep::io {

struct EsriGrid {
  std::size_t ncols = 0, nrows = 0;
  double x0 = 0.0, y0 = 0.0;  // lower-left corner of the lower-left cell
  double cellsize = 0.0;
  bool has_nodata = false;
  double nodata = 0.0;
  std::vector<double> values;  // row-major, row 0 the northernmost

  // The value of the cell holding p (cells are closed at their lower-left edges; the
  // grid's upper and right edges belong to the last cells); `outside` beyond the grid or
  // on a no-data cell.
  double at(const Point& p, double outside) const;
};

// Throws InputError("path:line: what is wrong") for a malformed file: a missing or repeated
// header key, a count or cell size that is not positive, a value that is not a number, too
// few or too many values.
EsriGrid read_esri_grid(const std::string& path);

}  // namespace meshstep::io
