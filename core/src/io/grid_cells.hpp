// The size of a raster, checked once for every grid reader (ESRI text grids as a size
// function and as heights, and GDAL's and PNG's rasters): a header's ncols x nrows is
// untrusted, and a product that wraps 64 bits would make a huge grid look small (or
// empty), so that a reader "finds" all its values and a consumer indexes past them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace meshstep::io::detail {

// The most samples a grid may have: a TIN names its samples with 32-bit indices.
inline constexpr std::uint64_t kMaxGridCells = std::uint64_t{1} << 32;

// ncols x nrows, computed without wrapping. Throws InputError(path, line, ...) when it is
// over kMaxGridCells, or over `room`, the most values the rest of the file can hold
// (nullopt: unknown, e.g. a pipe, or a compressed raster whose bytes say nothing).
std::uint64_t checked_grid_cells(const std::string& path, std::size_t line, std::uint64_t ncols, std::uint64_t nrows,
                                 std::optional<std::uint64_t> room);

}  // namespace meshstep::io::detail
