// Tiled terrain approximation: a grid bigger than memory, cut into tiles that are read,
// approximated and written one at a time, each independent of the others, whose TINs meet
// without cracks (docs/terrain.md, "Tiles").
//
// Layout. A tile is N x N samples, and neighbouring tiles share one column or row of
// samples: tile (r, c) covers the columns c(N - 1) .. min(c(N - 1) + N - 1, nx - 1) and the
// rows r(N - 1) .. min(r(N - 1) + N - 1, ny - 1), row 0 the southernmost as in HeightGrid.
// The last tiles of a row or column may be narrower (at least 2 samples).
//
// No cracks, by construction. Each of a tile's four sides is simplified on its own, in 1D,
// before the tile is refined: its ends (the tile's corners) are kept, then the sample of
// largest vertical error to the chord, until every sample is within the bound
// (simplify_profile). The side's samples are the neighbour's side too, taken in the same
// order (west to east, south to north), with the same corner heights, so both tiles get the
// same border vertices. The TIN starts from them and never inserts another sample on its
// rectangle (approximate_within_border): both TINs have exactly the same edges along the
// shared line, between vertices with the same global sample indices and heights.
//
// Corners without data. A corner is shared by up to four tiles that have no side in
// common, so its height must follow from what each of them sees: the rows are read
// northernmost first, and every tile with a corner on row j has seen the whole of rows j
// and up when it needs it. A corner without data takes (tile_corner_height):
//   1. the height of the nearest sample with data on its own grid row (ties: the western);
//   2. else, the row having no data at all, the nearest sample with data north of the row
//      in the corner's column, or else in the nearest column that has one (ties: western);
//   3. else (nothing north of the row either) 0.
// Elsewhere on a side, a sample without data carries no error (as in approximate()) and is
// never a vertex: chords simply pass over it.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "meshstep/io/surface_io.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"

namespace meshstep::terrain {

struct TileIndex {
  std::size_t row = 0, column = 0;  // r counts from the south, c from the west
  bool operator==(const TileIndex&) const = default;
};

struct TileLayout {
  std::size_t nx = 0, ny = 0;  // the grid's samples
  std::size_t size = 0;        // N: samples a tile side, at least 2

  std::size_t columns() const { return (nx - 1 + size - 2) / (size - 1); }  // ceil((nx - 1) / (N - 1))
  std::size_t rows() const { return (ny - 1 + size - 2) / (size - 1); }
  std::size_t first_column(std::size_t c) const { return c * (size - 1); }
  std::size_t last_column(std::size_t c) const { return std::min(first_column(c) + size - 1, nx - 1); }
  std::size_t first_row(std::size_t r) const { return r * (size - 1); }
  std::size_t last_row(std::size_t r) const { return std::min(first_row(r) + size - 1, ny - 1); }
};

// The samples of one side whose vertices the side keeps, besides its two ends: indices
// into `heights` (the side's samples in order, NaN for no data; at least 2), increasing.
// The ends stand at heights `first` and `last` (the corners'). Douglas-Peucker on the
// vertical error: a chord's worst sample (ties: the first) is kept while its error is over
// max_error - margin, the margin being two float32 steps of the side's largest |height|
// (2^-22 of it): the TIN measures the same samples again in 2D, with other rounding, and
// must find them within max_error. A side found within the bound keeps nothing.
std::vector<std::size_t> simplify_profile(std::span<const float> heights, float first, float last, double max_error);

// Rules 1 to 3 above: the height of a tile corner at column i of a grid row (`row`, its nx
// heights), where `north` holds, by column, the height of the nearest sample with data in
// that column on or north of the row (NaN: none).
float tile_corner_height(std::span<const float> row, std::span<const float> north, std::size_t i);

struct Tile {
  TileIndex index;
  std::size_t i0 = 0, j0 = 0;  // the grid column and row of the tile's sample (0, 0)
  // The tile's samples with the whole grid's spacing (its x0, y0 and units are the whole
  // grid's too: they describe the grid, not the tile).
  HeightGrid grid;
  // South-west, south-east, north-east, north-west: the sample's height, or the rule's.
  std::array<float, 4> corner_heights{};
};

// The vertices a tile's TIN starts from: its corners, and each side simplified within
// max_error.
BorderVertices tile_border(const Tile& tile, double max_error);

// A tile's TIN within options.max_error (its border within the same bound).
Tin approximate_tile(const Tile& tile, const TerrainOptions& options, TerrainReport* report = nullptr);

// The tile's TIN in the whole grid's metres: the sample at grid column i and row j at
// (i dx, j dy), as to_surface places it, so that a vertex two tiles share has the same
// three doubles in both. Triangles face up.
io::Surface tile_surface(const Tile& tile, const Tin& tin);

// Called with each tile as soon as its rows are in. The tile is gone after the call.
using TileVisitor = std::function<void(const Tile& tile)>;

// Cuts the grid at `path` into tiles of `size` samples a side while reading it row by row
// (read_height_grid_rows), northernmost first: every tile of a row of tiles as soon as its
// southern row is in, or, given `only`, that tile alone. One band of rows is held at a time:
// size x nx floats (size x size with `only`), besides the tile handed over. The whole file
// is read either way, so that a bad grid is refused whatever tile is asked for; a grid
// found bad part-way has handed over the tiles above the problem already. Throws
// InputError for a bad grid or an `only` outside the grid's tiles. Returns the grid's
// header (z empty).
HeightGrid cut_tiles(const std::string& path, const HeightGridOptions& options, std::size_t size,
                     std::optional<TileIndex> only, const TileVisitor& take);

// The same cut of a grid held in memory (tests; the rows are handed over as a file would).
void cut_tiles(const HeightGrid& grid, std::size_t size, std::optional<TileIndex> only, const TileVisitor& take);

}  // namespace meshstep::terrain
