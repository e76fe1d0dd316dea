// meshstep terrain GRID --tile N: a grid bigger than memory, approximated tile by tile
// (terrain/tiles.hpp), each tile written to a file of its own.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "console.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tiles.hpp"
#include "meshstep/terrain/tin.hpp"

namespace meshstep::app {

struct TiledTerrainRun {
  std::string grid;
  terrain::HeightGridOptions grid_options;
  std::size_t size = 0;                       // N
  std::optional<terrain::TileIndex> only;     // --tile-index R,C
  terrain::TerrainOptions options;            // max_error set
  double bound = 0.0;                         // the bound, in height units
  std::string algorithm;                      // its name, for the statistics
  std::string output;                         // OUT.EXT, or empty
  std::optional<io::SurfaceFormat> format;    // of output
  Verbosity verbosity = Verbosity::normal;
  bool stats_json = false;
};

// "R,C" as a tile index; nullopt if it is not two whole numbers separated by a comma.
std::optional<terrain::TileIndex> parse_tile_index(const std::string& text);

// The file tile `index` of output OUT.EXT goes to: OUT.rR-cC.EXT (OUT.r0-c0.obj for tile
// 0,0 of out.obj), in the folder of OUT.
std::string tile_output_path(const std::string& output, terrain::TileIndex index);

// The tile files of OUT.EXT already in OUT's folder (OUT.rR-cC.EXT), for the check that
// none of them is the grid: a tile still to be written cannot be.
std::vector<std::string> existing_tile_files(const std::string& output);

// Throws InputError when OUT's folder does not exist: said before the grid is read, not
// after its first band of rows (or a whole pass for its height range).
void check_tile_folder(const std::string& output);

// The lowest and highest height with data, in a pass over the grid that keeps no row (a
// --max-error in % of the range needs it before the first tile). Throws InputError.
std::pair<float, float> streamed_height_range(const std::string& path, const terrain::HeightGridOptions& options);

// Runs the tiles; returns the exit status. Throws InputError for a bad grid (after removing
// every tile file it wrote: a tile's file appears only once the whole grid has been read).
int run_tiled_terrain(const TiledTerrainRun& run);

}  // namespace meshstep::app
