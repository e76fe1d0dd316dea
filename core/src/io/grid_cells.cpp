// A raster's ncols x nrows, checked (io/grid_cells.hpp).
#include "io/grid_cells.hpp"

#include <string>

#include "meshstep/error.hpp"

namespace meshstep::io::detail {

std::uint64_t checked_grid_cells(const std::string& path, std::size_t line, std::uint64_t ncols, std::uint64_t nrows,
                                 std::optional<std::uint64_t> room) {
  const std::string size = std::to_string(ncols) + " x " + std::to_string(nrows);
  // Divided, not multiplied: the product itself may not fit 64 bits.
  if (ncols != 0 && nrows > kMaxGridCells / ncols)
    throw InputError(path, line,
                     size + " samples is too large a grid: at most " + std::to_string(kMaxGridCells) +
                         " samples are supported");
  const std::uint64_t cells = ncols * nrows;
  if (room && cells > *room)
    throw InputError(path, line,
                     size + " = " + std::to_string(cells) + " values, but the file can hold at most " +
                         std::to_string(*room) + ": the counts are wrong or the file is truncated");
  return cells;
}

}  // namespace meshstep::io::detail
