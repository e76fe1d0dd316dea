// Cutting a grid into tiles as its rows arrive, northernmost first (meshstep/terrain/tiles.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/terrain/tiles.hpp"
#include "planar_scale.hpp"

namespace meshstep::terrain {
namespace {

// Everything of a grid but its heights: its size, spacing, position and units.
void copy_header(const HeightGrid& from, HeightGrid& to) {
  to.nx = from.nx;
  to.ny = from.ny;
  to.dx = from.dx;
  to.dy = from.dy;
  to.x0 = from.x0;
  to.y0 = from.y0;
  to.geographic = from.geographic;
  to.units_note = from.units_note;
}

// Holds the band of rows of one row of tiles (the rows of a tile row r, from r(N - 1) up),
// hands its tiles over once its southern row is in, and starts the next band below with
// that row, which the two bands share.
class TileCutter {
 public:
  TileCutter(std::string path, std::size_t size, std::optional<TileIndex> only, const TileVisitor& take)
      : path_(std::move(path)), size_(size), only_(only), take_(take) {}

  void row(const HeightGrid& header, std::size_t j, std::span<const float> heights) {
    if (j == header.ny - 1) start(header);
    // The nearest data north in each column, this row included.
    for (std::size_t i = 0; i < north_.size(); ++i)
      if (!std::isnan(heights[i])) north_[i] = heights[i];
    const bool top = j == layout_.last_row(band_), bottom = j == layout_.first_row(band_);
    if (top) top_corners_ = corner_heights(heights);
    if (bottom) bottom_corners_ = corner_heights(heights);
    if (!only_ || only_->row == band_) store(j - layout_.first_row(band_), heights);
    if (!bottom) return;
    if (!only_ || only_->row == band_) hand_over(header);
    if (band_ == 0) return;
    // The next band down starts with this row, its northern one.
    --band_;
    top_corners_ = bottom_corners_;
    if (!only_ || only_->row == band_) store(j - layout_.first_row(band_), heights);
  }

 private:
  void start(const HeightGrid& header) {
    if (size_ < 2) throw InputError("a tile needs at least 2 x 2 samples, not " + std::to_string(size_));
    // The whole grid's rule, before any tile: a tile's own extent may be within the doubles
    // where its place in the grid (tile_surface) is not.
    detail::planar_scale(header);
    // A tile larger than the grid is the grid: the same layout, and a band no larger.
    layout_ = {header.nx, header.ny, std::min(size_, std::max(header.nx, header.ny))};
    if (only_ && (only_->row >= layout_.rows() || only_->column >= layout_.columns()))
      throw InputError(path_, 0,
                       "tile " + std::to_string(only_->row) + "," + std::to_string(only_->column) +
                           " is outside the grid: its " + std::to_string(header.nx) + " x " +
                           std::to_string(header.ny) + " samples make " + std::to_string(layout_.rows()) +
                           " rows x " + std::to_string(layout_.columns()) + " columns of tiles of " +
                           std::to_string(size_) + " samples a side (rows 0.." + std::to_string(layout_.rows() - 1) +
                           ", columns 0.." + std::to_string(layout_.columns() - 1) + ")");
    band_ = layout_.rows() - 1;
    north_.assign(header.nx, std::numeric_limits<float>::quiet_NaN());
    // With `only`, the tile's own columns alone.
    first_kept_ = only_ ? layout_.first_column(only_->column) : 0;
    width_ = only_ ? layout_.last_column(only_->column) - first_kept_ + 1 : header.nx;
    rows_.assign(std::min(layout_.size, header.ny) * width_, 0.0f);
  }

  // The corner heights of a row at every tile corner column (with `only`, those of the
  // tile's two columns; the others are left 0 and never used).
  std::vector<float> corner_heights(std::span<const float> heights) const {
    std::vector<float> corners(layout_.columns() + 1, 0.0f);
    for (std::size_t c = 0; c <= layout_.columns(); ++c) {
      if (only_ && c != only_->column && c != only_->column + 1) continue;
      const std::size_t i = c == layout_.columns() ? layout_.nx - 1 : layout_.first_column(c);
      corners[c] = tile_corner_height(heights, north_, i);
    }
    return corners;
  }

  void store(std::size_t slot, std::span<const float> heights) {
    std::copy_n(heights.begin() + static_cast<std::ptrdiff_t>(first_kept_), width_,
                rows_.begin() + static_cast<std::ptrdiff_t>(slot * width_));
  }

  void hand_over(const HeightGrid& header) {
    const std::size_t j0 = layout_.first_row(band_), ny = layout_.last_row(band_) - j0 + 1;
    for (std::size_t c = 0; c < layout_.columns(); ++c) {
      if (only_ && c != only_->column) continue;
      Tile tile;
      tile.index = {band_, c};
      tile.i0 = layout_.first_column(c);
      tile.j0 = j0;
      HeightGrid& g = tile.grid;
      copy_header(header, g);
      g.nx = layout_.last_column(c) - tile.i0 + 1;
      g.ny = ny;
      g.z.resize(g.nx * g.ny);
      for (std::size_t j = 0; j < ny; ++j)
        std::copy_n(rows_.begin() + static_cast<std::ptrdiff_t>(j * width_ + tile.i0 - first_kept_), g.nx,
                    g.z.begin() + static_cast<std::ptrdiff_t>(j * g.nx));
      tile.corner_heights = {bottom_corners_[c], bottom_corners_[c + 1], top_corners_[c + 1], top_corners_[c]};
      take_(tile);
    }
  }

  std::string path_;
  std::size_t size_;
  std::optional<TileIndex> only_;
  const TileVisitor& take_;
  TileLayout layout_;
  std::size_t band_ = 0;                 // the row of tiles whose rows are coming in
  std::vector<float> north_;             // by column: the nearest data at or north of the row
  std::vector<float> top_corners_, bottom_corners_;  // the band's corner heights, by tile column
  std::size_t first_kept_ = 0, width_ = 0;           // the columns kept
  std::vector<float> rows_;              // the band: slot s holds grid row first_row(band_) + s
};

}  // namespace

HeightGrid cut_tiles(const std::string& path, const HeightGridOptions& options, std::size_t size,
                     std::optional<TileIndex> only, const TileVisitor& take) {
  TileCutter cutter(path, size, only, take);
  return read_height_grid_rows(path, options, [&](const HeightGrid& header, std::size_t j, std::span<const float> z) {
    cutter.row(header, j, z);
  });
}

void cut_tiles(const HeightGrid& grid, std::size_t size, std::optional<TileIndex> only, const TileVisitor& take) {
  if (grid.nx < 2 || grid.ny < 2) throw InputError("a terrain needs a grid of at least 2 x 2 samples");
  TileCutter cutter("", size, only, take);
  HeightGrid header;  // the grid but its heights (not copied: the rows are the grid's own)
  copy_header(grid, header);
  for (std::size_t j = grid.ny; j-- > 0;)
    cutter.row(header, j, std::span<const float>(grid.z).subspan(j * grid.nx, grid.nx));
}

}  // namespace meshstep::terrain
