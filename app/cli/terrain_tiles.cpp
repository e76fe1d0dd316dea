#include "terrain_tiles.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <vector>

#include "command.hpp"
#include "json_line.hpp"
#include "meshstep/error.hpp"

namespace meshstep::app {
namespace {

// Tile files written under a hidden name beside their final one and renamed into place
// only once the whole grid has been read: a grid found bad in its last row leaves no tile
// of it behind (the tiles above the bad row were written long before). Whatever has not
// been committed is removed on destruction.
class StagedTileFiles {
 public:
  StagedTileFiles() = default;
  StagedTileFiles(const StagedTileFiles&) = delete;
  StagedTileFiles& operator=(const StagedTileFiles&) = delete;
  ~StagedTileFiles() {
    std::error_code ec;
    for (const auto& f : files_) std::filesystem::remove(f.staged, ec);
  }

  // The hidden name to write `final_path` under for now.
  std::string stage(const std::string& final_path) {
    const std::filesystem::path p(final_path);
    const std::string staged =
        (p.parent_path() / ("." + p.filename().string() + ".staged." + std::to_string(::getpid()))).string();
    files_.push_back({staged, final_path});
    return staged;
  }

  void commit() {
    for (auto& f : files_) {
      std::error_code ec;
      std::filesystem::rename(f.staged, f.final_path, ec);
      if (ec) throw InputError(f.final_path, 0, "cannot rename the finished tile into place: " + ec.message());
    }
    files_.clear();
  }

 private:
  struct File {
    std::string staged, final_path;
  };
  std::vector<File> files_;
};

// What the tiles add up to.
struct TileTotals {
  std::size_t tiles = 0, triangles = 0, vertices = 0, capped = 0;
  double max_error = 0.0;
  double approximate_ms = 0.0;
};

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
}

// A vertex of a tile is counted once over all the tiles: a tile leaves its western and
// southern sides to the neighbours there, which have them as their eastern and northern.
std::size_t vertices_owned(const terrain::Tile& tile, const terrain::Tin& tin, bool alone) {
  if (alone) return tin.samples.size();
  std::size_t owned = 0;
  for (const std::uint32_t s : tin.samples) {
    const std::size_t i = s % tile.grid.nx, j = s / tile.grid.nx;
    owned += (i > 0 || tile.index.column == 0) && (j > 0 || tile.index.row == 0);
  }
  return owned;
}

std::string tile_name(terrain::TileIndex index) {
  return std::to_string(index.row) + "," + std::to_string(index.column);
}

}  // namespace

std::optional<terrain::TileIndex> parse_tile_index(const std::string& text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  terrain::TileIndex index;
  const auto whole = [](const char* first, const char* last, std::size_t& value) {
    const auto [end, ec] = std::from_chars(first, last, value);
    return first != last && ec == std::errc() && end == last;
  };
  if (!whole(text.data(), text.data() + comma, index.row) ||
      !whole(text.data() + comma + 1, text.data() + text.size(), index.column))
    return std::nullopt;
  return index;
}

std::string tile_output_path(const std::string& output, terrain::TileIndex index) {
  const std::size_t slash = output.find_last_of('/');
  std::size_t dot = output.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) dot = output.size();
  return output.substr(0, dot) + ".r" + std::to_string(index.row) + "-c" + std::to_string(index.column) +
         output.substr(dot);
}

std::vector<std::string> existing_tile_files(const std::string& output) {
  const std::string pattern = tile_output_path(output, {0, 0});  // OUT.r0-c0.EXT
  const std::size_t r = pattern.rfind(".r0-c0");
  const std::string head = pattern.substr(0, r) + ".r", tail = pattern.substr(r + 6);
  // Digits, '-c', digits between head and tail.
  const auto is_tile = [&](const std::string& path) {
    if (path.size() <= head.size() + tail.size() || !path.starts_with(head) || !path.ends_with(tail)) return false;
    const std::string middle = path.substr(head.size(), path.size() - head.size() - tail.size());
    const std::size_t dash = middle.find("-c");
    const auto digits = [](const std::string& t) {
      return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    return dash != std::string::npos && digits(middle.substr(0, dash)) && digits(middle.substr(dash + 2));
  };
  std::vector<std::string> tiles;
  const std::filesystem::path folder = std::filesystem::path(output).parent_path();
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder.empty() ? "." : folder, ec), end; !ec && it != end;
       it.increment(ec)) {
    // The entry's name under OUT's own spelling of the folder, to compare with head and tail.
    const std::string name = (folder / it->path().filename()).string();
    if (is_tile(name)) tiles.push_back(name);
  }
  return tiles;
}

void check_tile_folder(const std::string& output) {
  const std::filesystem::path folder = std::filesystem::path(output).parent_path();
  std::error_code ec;
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
    throw InputError(output, 0, "cannot write the tiles: the folder " + folder.string() + " does not exist");
}

std::pair<float, float> streamed_height_range(const std::string& path, const terrain::HeightGridOptions& options) {
  float low = INFINITY, high = -INFINITY;
  terrain::read_height_grid_rows(path, options, [&](const terrain::HeightGrid&, std::size_t, std::span<const float> z) {
    for (const float h : z)
      if (!std::isnan(h)) {
        low = std::min(low, h);
        high = std::max(high, h);
      }
  });
  return {low, high};  // the reader refuses a grid without data
}

int run_tiled_terrain(const TiledTerrainRun& run) {
  Stopwatch clock;
  StagedTileFiles staged;
  TileTotals totals;
  const auto take = [&](const terrain::Tile& tile) {
    terrain::TerrainReport report;
    const terrain::Tin tin = terrain::approximate_tile(tile, run.options, &report);
    const terrain::ErrorMeasure error = terrain::measure_error(tile.grid, tin);
    if (error.uncovered > 0 || (!report.capped && error.max > run.bound))
      // Never write a TIN its own measure rejects (nor any tile of the run: see StagedTileFiles).
      throw InputError(run.grid, 0,
                       "internal: tile " + tile_name(tile.index) + " misses its bound (" + std::to_string(error.max) +
                           " > " + std::to_string(run.bound) + ", " + std::to_string(error.uncovered) +
                           " samples uncovered)");
    ++totals.tiles;
    totals.triangles += tin.triangles.size();
    totals.vertices += vertices_owned(tile, tin, run.only.has_value());
    totals.capped += report.capped;
    totals.max_error = std::max(totals.max_error, error.max);
    totals.approximate_ms += report.seconds * 1000.0;
    if (!run.output.empty()) {
      const std::string path = tile_output_path(run.output, tile.index);
      try {
        io::write_surface(staged.stage(path), terrain::tile_surface(tile, tin), *run.format);
      } catch (const InputError& e) {
        throw InputError(path, 0, e.message());  // the name the user knows, not the staged one
      }
    }
    if (run.verbosity == Verbosity::verbose)
      std::fprintf(stderr,
                   "meshstep: tile %s: %zu x %zu samples from column %zu, row %zu: %zu triangles, largest error "
                   "%.6g, %.0f ms\n",
                   tile_name(tile.index).c_str(), tile.grid.nx, tile.grid.ny, tile.i0, tile.j0, tin.triangles.size(),
                   error.max, report.seconds * 1000.0);
  };

  print_progress(run.verbosity, "reading " + run.grid + " in tiles of " + std::to_string(run.size) + " x " +
                                    std::to_string(run.size) + " samples");
  const terrain::HeightGrid header = terrain::cut_tiles(run.grid, run.grid_options, run.size, run.only, take);
  staged.commit();
  const double total_ms = clock.lap_ms();

  const terrain::TileLayout layout{header.nx, header.ny, std::min(run.size, std::max(header.nx, header.ny))};
  const std::size_t band_rows = std::min(layout.size, header.ny);
  const double band_mib = 4.0 * static_cast<double>(band_rows) *
                          static_cast<double>(run.only ? std::min(layout.size, header.nx) : header.nx) / 1048576.0;
  if (totals.capped > 0)
    print_warning(run.verbosity, std::to_string(totals.capped) + " tile(s) stopped at --max-triangles with the bound unmet");
  if (run.verbosity != Verbosity::quiet) {
    const std::string where = run.output.empty() ? ""
                              : run.only          ? ", written to " + tile_output_path(run.output, *run.only)
                                                  : ", written to " + tile_output_path(run.output, {0, 0}) + " .. " +
                                               tile_output_path(run.output, {layout.rows() - 1, layout.columns() - 1});
    if (run.only)
      std::printf("%s: tile %s of %zu x %zu tiles of %zu samples -> %zu vertices, %zu triangles; largest error %.6g%s\n",
                  run.grid.c_str(), tile_name(*run.only).c_str(), layout.rows(), layout.columns(), run.size,
                  totals.vertices, totals.triangles, totals.max_error, where.c_str());
    else
      std::printf("%s: %zu x %zu samples in %zu x %zu tiles of %zu -> %zu vertices, %zu triangles; largest error "
                  "%.6g%s\n",
                  run.grid.c_str(), header.nx, header.ny, layout.rows(), layout.columns(), run.size, totals.vertices,
                  totals.triangles, totals.max_error, where.c_str());
    std::printf("  %.0f ms (%.0f approximating); peak memory %.1f MiB, of which the band of rows %.1f MiB\n", total_ms,
                totals.approximate_ms, peak_rss_mib(), band_mib);
  }
  if (run.stats_json) {
    JsonLine ms;
    ms.field("total", total_ms).field("approximate", totals.approximate_ms);
    JsonLine stats;
    stats.field("input", run.grid)
        .field("grid_columns", header.nx)
        .field("grid_rows", header.ny)
        .field("tile", run.size)
        .field("tile_rows", layout.rows())
        .field("tile_columns", layout.columns())
        .field("tiles", totals.tiles)
        .field("algorithm", run.algorithm)
        .field("bound", run.bound)
        .field("vertices", totals.vertices)
        .field("triangles", totals.triangles)
        .field("max_error", totals.max_error)
        .field("capped", totals.capped > 0)
        .field("band_mib", band_mib)
        .field("peak_rss_mib", peak_rss_mib())
        .object("ms", ms);
    std::printf("%s\n", stats.str().c_str());
  }
  return kExitOk;
}

}  // namespace meshstep::app
