// ESRI ASCII grids (.asc): a raster of values over a rectangle, used as a size function
// (`meshstep refine --size GRID.asc`) and as terrain heights (terrain/height_grid.hpp).
//
//   ncols N / nrows M / xllcorner X (or xllcenter) / yllcorner Y (or yllcenter) /
//   cellsize C / [NODATA_value V] / then M rows of N values, the first row the northernmost.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
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

  // The lines (1-based) the header's keys were read from (0: absent), so that a caller's
  // checks of what the header means, which the reader cannot judge, still name the line:
  // a terrain needs 2 x 2 samples, and a grid whose every value is NODATA_value has none.
  struct HeaderLines {
    std::size_t ncols = 0, nrows = 0, x0 = 0, y0 = 0, cellsize = 0, nodata = 0;
  } lines;

  // ncols x nrows: the reader has checked that it neither wraps nor passes 2^32, nor the
  // values the file can hold (io/grid_cells.hpp).
  std::size_t cell_count() const { return ncols * nrows; }

  // The value of the cell holding p (cells are closed at their lower-left edges; the
  // grid's upper and right edges belong to the last cells); `outside` beyond the grid or
  // on a no-data cell.
  double at(const Point& p, double outside) const;
};

// Throws InputError("path:line: what is wrong") for a malformed file: a missing or repeated
// header key, a count or cell size that is not positive (at its own line), counts whose
// product (never computed wrapped) is over 2^32 or over the values the file's bytes can
// hold (at the later count's line), a value that is
// not a finite number (NaN and infinities are refused: no-data cells are marked by
// NODATA_value), too few values (at the last line) or too many (at the first extra one).
EsriGrid read_esri_grid(const std::string& path);

// One row of values, northernmost first: `header` is the grid read so far (its values
// empty), `row` the row's index (0 the northernmost), `values` its ncols values, `line`
// the line of its last value. It may throw, e.g. InputError at `line`.
using EsriRowVisitor =
    std::function<void(const EsriGrid& header, std::size_t row, std::span<const double> values, std::size_t line)>;

// As read_esri_grid, with the same checks, but hands the values over one row at a time
// and keeps none of them (the result's values are empty): for a caller that stores them
// in its own form, e.g. as floats, without first holding the whole grid as doubles. Rows
// are handed over as they complete, so a file found short or long at the end has already
// delivered its complete rows.
EsriGrid read_esri_grid_rows(const std::string& path, const EsriRowVisitor& visit);

}  // namespace meshstep::io
