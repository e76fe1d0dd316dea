// Height grids: the input of terrain approximation (terrain/tin.hpp), a regular raster of
// heights read from an ESRI ASCII grid (.asc) or a greyscale PNG heightmap (.png).
//
// Samples and spacing. Sample (i, j) is column i of row j; row 0 is the southernmost, so x
// grows with i and y with j, and the sample sits at (i * dx, j * dy) in metres from sample
// (0, 0). An ESRI grid's samples are its cell centres; a PNG's are its pixels.
//
// Geographic grids. An ESRI grid whose cell size is in degrees (latitude/longitude, e.g.
// SRTM's 3 arc-second tiles) has cells that are not square on the ground. Its cell size is
// converted to metres once, at the grid's central latitude phi, on a spherical Earth of the
// IUGG mean radius R = 6371008.8 m:
//     dy = R * dphi            (dphi, dlambda: the cell size in radians)
//     dx = R * cos(phi) * dlambda
// The sphere is within 0.6% of the WGS 84 ellipsoid's north-south and east-west scales at any
// latitude, and taking cos(phi) at the centre errs by about tan(phi) * (half the grid's
// latitude span in radians) at its northern and southern edges: 0.2% for a 0.3-degree tile
// at 36 degrees N. That is well inside what a TIN within a vertical error cares about (it
// only makes the planar triangle shapes a little off), and it keeps the grid regular.
// A grid reads as geographic when its cells are at most one arc-minute (1/60 degree) and
// it lies wholly within longitude -180..180 and latitude -90..90: a metric grid would need
// centimetre cells near its own origin to pass. HeightGridOptions::geographic overrides the
// guess either way; units_note says what was decided and why.
//
// Memory. z is float32, one allocation of nx * ny (a float holds a height in metres to
// 0.5 mm up to 8 km). The ESRI reader hands values over row by row as doubles, so no
// double copy of the grid is ever held; a PNG is decoded whole by stb_image first
// (2 bytes a pixel for 16-bit grey), then converted.
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace meshstep::terrain {

// The IUGG mean Earth radius R1 = (2a + b) / 3 of WGS 84, in metres.
inline constexpr double kEarthMeanRadius = 6371008.8;

struct HeightGridOptions {
  // PNG heightmaps carry no units: each pixel is a png_cell x png_cell metre sample, and
  // its height is raw / 255 (8-bit) or raw / 65535 (16-bit), a value in [0, 1], times
  // png_z_scale. That is how fogleman's hmm reads a PNG (its -z option is png_z_scale),
  // so errors and triangle counts compare with it directly. Both must be positive.
  double png_cell = 1.0;
  double png_z_scale = 1.0;
  // ESRI grids: true reads the cell size as degrees, false as metres; unset guesses (see
  // above). A PNG has no position on Earth: true is refused for one.
  std::optional<bool> geographic;
};

struct HeightGrid {
  std::size_t nx = 0, ny = 0;  // samples per row, rows
  double dx = 0, dy = 0;       // sample spacing in metres (east-west, north-south)
  double x0 = 0, y0 = 0;       // position of sample (0, 0) in the grid's own units (informative)
  std::vector<float> z;        // row-major, row 0 the southernmost; NaN = no data
  bool geographic = false;     // the cell size was given in degrees and converted
  // How the grid's units were read, for the user: e.g. "3 arc-second cells at 36.6 N:
  // 74.4 m x 92.6 m (spherical Earth, R = 6371008.8 m)".
  std::string units_note;

  // A grid can hold 1 x N samples (a profile), but a TIN needs at least 2 x 2:
  // read_height_grid refuses smaller grids, and code that builds a grid in memory should
  // refuse one too (approximate() does) rather than produce a TIN without triangles.
  float at(std::size_t i, std::size_t j) const { return z[j * nx + i]; }  // column i of row j
  bool has_data(std::size_t i, std::size_t j) const { return !std::isnan(at(i, j)); }
  // The lowest and highest height among the samples with data; throws InputError when no
  // sample has any.
  std::pair<float, float> height_range() const;
  std::size_t data_count() const;  // samples with data
};

// high - low of a height range, in double: two floats' difference can pass a float's
// range (heights from -3e38 to 3e38 span 6e38), and a percentage of an infinite span is
// no bound at all.
inline double height_span(std::pair<float, float> range) {
  return static_cast<double>(range.second) - static_cast<double>(range.first);
}

// Reads a grid by its file name's extension (case-insensitive): .asc an ESRI ASCII grid
// (NODATA_value cells become NaN), .png an 8- or 16-bit greyscale heightmap (every pixel
// has data, except those an alpha channel makes fully transparent; a colour PNG is read
// only when every pixel is grey, R = G = B, since a colour encoding of heights such as
// terrain-RGB would otherwise be read silently wrong).
//
// Throws InputError "FILE:LINE: what is wrong" for a malformed text grid and "FILE: what
// is wrong" for a PNG or an unknown extension: counts that are not positive integers, a
// non-positive cell size, values that are not finite numbers or do not fit a float, more
// or fewer values than the header declares, fewer than 2 x 2 samples ("needs at least
// 2 x 2 samples"), no sample with data.
HeightGrid read_height_grid(const std::string& path, const HeightGridOptions& options = {});

// One row of heights: `header` is the grid as read so far (its sizes, spacing, units and
// position; z empty), `j` the row, `heights` its nx samples (NaN: no data). Rows come
// northernmost first, as an ESRI grid stores them: j = ny - 1 down to 0.
using HeightRowVisitor =
    std::function<void(const HeightGrid& header, std::size_t j, std::span<const float> heights)>;

// As read_height_grid, with the same checks and errors, but the rows are handed over one at
// a time and none is kept (the result's z is empty): the tiles of a grid bigger than memory
// (terrain/tiles.hpp). An ESRI grid is streamed, one row of doubles held at a time; a PNG
// is decoded whole first (stb_image cannot stream), then handed over row by row. A grid
// found bad part-way (a bad value, too few values, no data at all) has already handed over
// the rows before the problem: a caller keeps nothing it made of them until this returns.
HeightGrid read_height_grid_rows(const std::string& path, const HeightGridOptions& options,
                                 const HeightRowVisitor& visit);

}  // namespace meshstep::terrain
