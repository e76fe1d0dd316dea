// meshstep terrain: a height grid to a small TIN within a vertical error.
#include <charconv>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include "command.hpp"
#include "console.hpp"
#include "refuse_overwrites.hpp"
#include "json_line.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/replay/run_header.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"
#include "record_option.hpp"
#include "terrain_output.hpp"
#include "terrain_tiles.hpp"

namespace meshstep::app {
namespace {

struct TerrainArgs {
  std::string grid;
  std::string max_error;
  std::size_t max_triangles = 0;
  std::string algorithm = "lepp-surface";
  std::string terminal = "centroid";
  std::string ds = "tds";
  bool flips = false;
  bool improve = false, no_improve = false;
  std::string output;
  double base = 0.0;
  double png_cell = 1.0;
  double z_scale = 1.0;
  std::string geographic = "auto";
  std::string stats;
  long long tile = -1;      // --tile N (-1: not given, the whole grid at once)
  std::string tile_index;   // --tile-index R,C
  std::string record;       // --record LOG
  bool quiet = false;
  bool verbose = false;
};

// "E" in height units, or "P%" of the height range.
std::optional<double> parse_error_bound(const std::string& text, double height_range) {
  const bool percent = !text.empty() && text.back() == '%';
  const std::string number = percent ? text.substr(0, text.size() - 1) : text;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (ec != std::errc() || end != number.data() + number.size() || !(value >= 0.0)) return std::nullopt;
  return percent ? value / 100.0 * height_range : value;
}

void print_stats_json(const TerrainArgs& args, const terrain::HeightGrid& grid, double bound,
                      const terrain::TerrainReport& report, const terrain::ErrorMeasure& error,
                      const terrain::AngleStats& angles, double read_ms, double write_ms) {
  JsonLine histogram_fields;
  for (std::size_t k = 0; k < angles.histogram.size(); ++k)
    histogram_fields.field(std::to_string(10 * k), angles.histogram[k]);
  JsonLine ms;
  ms.field("read", read_ms).field("approximate", report.seconds * 1000.0).field("write", write_ms);
  JsonLine stats;
  stats.field("input", args.grid)
      .field("grid_columns", grid.nx)
      .field("grid_rows", grid.ny)
      .field("algorithm", args.algorithm)
      .field("bound", bound)
      .field("vertices", report.vertices)
      .field("triangles", report.triangles)
      .field("max_error", error.max)
      .field("rms_error", error.rms)
      .field("samples", error.samples)
      .field("capped", report.capped)
      .field("terminal_worst", report.terminal_worst)
      .field("terminal_points", report.terminal_points)
      .field("removed_vertices", report.removed)
      .field("flips_3d", report.flips_3d)
      .field("min_angle_3d", angles.smallest_deg)
      .field("share_under_10", angles.share_under_10)
      .field("share_under_20", angles.share_under_20)
      .field("share_under_30", angles.share_under_30)
      .object("angle_histogram_3d", histogram_fields)
      .object("ms", ms);
  std::printf("%s\n", stats.str().c_str());
}

// The options approximate() and approximate_tile() share, but for the bound.
terrain::TerrainOptions terrain_options(const TerrainArgs& args, const terrain::TerrainAlgorithmInfo& algorithm) {
  terrain::TerrainOptions options;
  options.algorithm = algorithm.algorithm;
  options.terminal_point =
      args.terminal == "midpoint" ? terrain::TerminalPoint::midpoint : terrain::TerminalPoint::centroid;
  options.max_triangles = args.max_triangles;
  options.data_structure = args.ds == "dcel" ? DataStructure::dcel : DataStructure::tds;
  options.flips_3d = args.flips;
  // lepp-surface improves by default; greedy stays the Garland-Heckbert baseline.
  options.improve = args.improve || (algorithm.algorithm == terrain::TerrainAlgorithm::lepp_surface && !args.no_improve);
  return options;
}

// --tile N [--tile-index R,C]: the checks of what tiles cannot do, the bound (a first pass
// over the grid for a bound in %), then the tiles (terrain_tiles.hpp).
int run_terrain_in_tiles(const TerrainArgs& args, const terrain::TerrainAlgorithmInfo& algorithm,
                         const std::optional<io::SurfaceFormat>& format,
                         const terrain::HeightGridOptions& grid_options) {
  if (args.tile < 2) {
    print_error(args.tile == -1 ? "--tile-index needs --tile N"
                                : "--tile " + std::to_string(args.tile) +
                                      ": a tile needs at least 2 x 2 samples (--tile N, N >= 2)");
    return kExitUsage;
  }
  if (args.max_error.empty()) {
    // Without a bound a side could only keep every sample: a cap cannot be shared by two tiles.
    print_error("--tile needs --max-error: each tile's sides are simplified within it, the same way by both "
                "neighbours (--max-triangles then caps each tile)");
    return kExitUsage;
  }
  TiledTerrainRun run;
  if (!args.tile_index.empty()) {
    run.only = parse_tile_index(args.tile_index);
    if (!run.only) {
      print_error("--tile-index: '" + args.tile_index + "' is not ROW,COLUMN (two whole numbers from 0, e.g. 0,3)");
      return kExitUsage;
    }
  }
  if (!args.output.empty() && (!format || *format == io::SurfaceFormat::stl_binary)) {
    print_error(args.output +
                ": tiles are written as .obj, .off or .ply (exact doubles, so that shared vertices weld; STL "
                "rounds them to float)");
    return kExitUsage;
  }
  if (args.base > 0.0) {
    print_error("--base closes one surface into a solid: it does not go with --tile (join the tiles first)");
    return kExitUsage;
  }
  if (!args.record.empty()) {
    print_error("--record records one run: it does not go with --tile (record one tile's grid on its own)");
    return kExitUsage;
  }
  const Verbosity verbosity =
      args.quiet ? Verbosity::quiet : args.verbose ? Verbosity::verbose : Verbosity::normal;
  if (!parse_error_bound(args.max_error, 1.0)) {
    print_error("--max-error: '" + args.max_error + "' is not a number >= 0 (or a percentage like 0.5%)");
    return kExitUsage;
  }
  try {
    if (!args.output.empty()) check_tile_folder(args.output);
    double range = 0.0;
    if (args.max_error.back() == '%') {
      // Every tile needs the same bound, so the whole grid's range comes first.
      print_progress(verbosity, "reading " + args.grid + " once for its height range");
      // The same span, in double, as the whole-grid run takes: the same bound.
      range = terrain::height_span(streamed_height_range(args.grid, grid_options));
    }
    const double bound = *parse_error_bound(args.max_error, range);
    run.grid = args.grid;
    run.grid_options = grid_options;
    run.size = static_cast<std::size_t>(args.tile);
    run.options = terrain_options(args, algorithm);
    run.options.max_error = bound;
    run.bound = bound;
    run.algorithm = args.algorithm;
    run.output = args.output;
    run.format = format;
    run.verbosity = verbosity;
    run.stats_json = args.stats == "json";
    return run_tiled_terrain(run);
  } catch (const InputError& e) {
    print_error(input_error_text(args.grid, e));
    return kExitBadInput;
  }
}

int run_terrain(const TerrainArgs& args) {
  const Verbosity verbosity =
      args.quiet ? Verbosity::quiet : args.verbose ? Verbosity::verbose : Verbosity::normal;
  const auto* algorithm = terrain::find_terrain_algorithm(args.algorithm);
  if (!algorithm) {
    print_error("unknown terrain algorithm '" + args.algorithm + "' (meshstep list shows them)");
    return kExitUsage;
  }
  if (args.max_error.empty() && args.max_triangles == 0) {
    print_error("give --max-error, --max-triangles or both");
    return kExitUsage;
  }
  std::optional<io::SurfaceFormat> format;
  if (!args.output.empty() && io::mesh_prefix_of(args.output) == args.output) {
    format = io::surface_format_for(args.output);
    if (!format) {
      print_error(args.output + ": unknown output format (use .obj, .off, .ply, .stl or .node)");
      return kExitUsage;
    }
  }

  if (args.base > 0.0 && !args.output.empty() && !format) {
    print_error("--base makes a solid: it needs a surface output (.obj, .off, .ply, .stl)");
    return kExitUsage;
  }
  const terrain::HeightGridOptions grid_options{
      .png_cell = args.png_cell,
      .png_z_scale = args.z_scale,
      .geographic = args.geographic == "auto" ? std::nullopt : std::optional<bool>(args.geographic == "yes")};
  const bool in_tiles = args.tile != -1 || !args.tile_index.empty();
  FileRoles files;
  files.reads(args.grid).writes_log("--record", args.record);
  if (in_tiles && !args.output.empty()) files.writes_existing("-o", args.output, existing_tile_files(args.output), "output");
  else if (format) files.writes("-o", args.output, "output");
  else if (!args.output.empty()) files.writes_mesh("-o", args.output.substr(0, args.output.rfind('.')), args.output);
  if (const int refused = refuse_overwrites(files)) return refused;
  if (in_tiles) return run_terrain_in_tiles(args, *algorithm, format, grid_options);

  Stopwatch clock;
  try {
    print_progress(verbosity, "reading " + args.grid);
    const terrain::HeightGrid grid = terrain::read_height_grid(args.grid, grid_options);
    const double read_ms = clock.lap_ms();
    if (grid.geographic) print_progress(verbosity, grid.units_note);
    const double range = terrain::height_span(grid.height_range());
    double bound = std::numeric_limits<double>::infinity();
    if (!args.max_error.empty()) {
      const auto parsed = parse_error_bound(args.max_error, range);
      if (!parsed) {
        print_error("--max-error: '" + args.max_error + "' is not a number >= 0 (or a percentage like 0.5%)");
        return kExitUsage;
      }
      bound = *parsed;
    }

    terrain::TerrainOptions options = terrain_options(args, *algorithm);
    options.max_error = args.max_error.empty() ? 0.0 : bound;  // without a bound: to the cap
    Stopwatch since_progress;
    double quiet_ms = 0.0;
    if (verbosity != Verbosity::quiet) {
      options.progress = [&](std::size_t triangles, double worst) {
        quiet_ms += since_progress.lap_ms();
        if (quiet_ms < 1000.0) return;
        quiet_ms = 0.0;
        std::fprintf(stderr, "meshstep: terrain: %zu triangles, largest error %.6g\n", triangles, worst);
      };
    }
    print_progress(verbosity, "approximating a " + std::to_string(grid.nx) + " x " + std::to_string(grid.ny) +
                                  " grid with " + args.algorithm + ", largest error " + std::to_string(bound));
    // The header says what a viewer needs to explain a step: the bound, the grid and its
    // spacing (a step's sample is a grid index), the choices made.
    std::unique_ptr<replay::LogWriter> log;
    if (!args.record.empty()) {
      log = open_log(args.record, args.grid, args.algorithm, replay::terrain_parameters(options, grid),
                     options.data_structure, Insertion::flip, nullptr);
      options.record = log.get();
    }
    terrain::TerrainReport report;
    const terrain::Tin tin = terrain::approximate(grid, options, &report);
    clock.lap_ms();
    const terrain::ErrorMeasure error = terrain::measure_error(grid, tin);
    if (error.uncovered > 0 || (!report.capped && error.max > bound)) {
      // Never write a TIN its own measure rejects.
      print_error(args.grid + ": internal: the TIN misses its bound (" + std::to_string(error.max) + " > " +
                  std::to_string(bound) + ", " + std::to_string(error.uncovered) + " samples uncovered)");
      return kExitBadInput;
    }
    if (report.capped)
      print_warning(verbosity, "stopped at --max-triangles " + std::to_string(args.max_triangles) +
                                   " with the largest error at " + std::to_string(error.max));
    double write_ms = 0.0;
    if (!args.output.empty()) {
      print_progress(verbosity, "writing " + args.output);
      write_terrain(args.output, format, grid, tin, args.base);
      write_ms = clock.lap_ms();
    }
    if (log) {
      log->finish();
      print_progress(verbosity, record_summary(*log));
    }
    const terrain::AngleStats angles = terrain::angle_stats_3d(grid, tin);
    if (verbosity != Verbosity::quiet) {
      std::printf("%s: %zu x %zu samples -> %zu vertices, %zu triangles; largest error %.6g (rms %.6g)%s\n",
                  args.grid.c_str(), grid.nx, grid.ny, report.vertices, report.triangles, error.max, error.rms,
                  args.output.empty() ? "" : (", written to " + args.output).c_str());
      std::printf("  3D angles: smallest %.2f; under 20 degrees: %.1f%% of triangles; %.0f ms\n",
                  angles.smallest_deg, 100.0 * angles.share_under_20, report.seconds * 1000.0);
    }
    if (args.stats == "json") print_stats_json(args, grid, bound, report, error, angles, read_ms, write_ms);
  } catch (const InputError& e) {
    print_error(input_error_text(args.grid, e));
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace

Command add_terrain_command(CLI::App& parent) {
  auto args = std::make_shared<TerrainArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "terrain",
      "Approximate a height grid by a triangulated irregular network (TIN): grid samples as\n"
      "vertices, Delaunay in the plane, every sample within --max-error of the surface.");
  cmd->add_option("GRID", args->grid, "Height grid: ESRI ASCII (.asc), a greyscale PNG heightmap (8 or 16 bit), or a\n"
                  "GeoTIFF (.tif) or any raster GDAL reads (when meshstep is built with GDAL)")
      ->required();
  cmd->add_option("--max-error", args->max_error,
                  "Largest vertical error, in height units, or with a % suffix as a share of\n"
                  "the grid's height range (0.5%)");
  cmd->add_option("--max-triangles", args->max_triangles, "Stop at this many triangles (0: no cap)");
  cmd->add_option("-a,--algorithm", args->algorithm, "lepp-surface or greedy (meshstep list describes them)")
      ->capture_default_str();
  cmd->add_option("--terminal", args->terminal,
                  "lepp-surface's point on a terminal edge: centroid of the terminal triangles,\n"
                  "or midpoint of the edge")
      ->check(CLI::IsMember({"centroid", "midpoint"}))
      ->capture_default_str();
  CLI::Option* improve = cmd->add_flag("--improve", args->improve,
                "After refining, remove every vertex whose removal keeps every sample within\n"
                "the bound and does not lower the smallest 3D angle round it (the default for\n"
                "lepp-surface; this asks it of greedy too)");
  cmd->add_flag("--no-improve", args->no_improve, "lepp-surface without the improvement")->excludes(improve);
  cmd->add_flag("--flips", args->flips,
                "Then flip every edge whose flip raises the smallest 3D angle of its two\n"
                "triangles and keeps them within the bound (no longer Delaunay in the plane)");
  cmd->add_option("--ds", args->ds, "Mesh data structure: tds or dcel")
      ->check(CLI::IsMember({"tds", "dcel"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", args->output,
                  "Write the TIN: .obj, .off, .ply (binary), .stl (binary), or PREFIX.node for\n"
                  "Triangle's .node/.ele with the height as the vertex attribute");
  cmd->add_option("--base", args->base,
                  "Close the surface with walls and a flat bottom this far below the lowest\n"
                  "sample (a solid for printing; surface formats only)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--png-cell", args->png_cell, "A PNG heightmap's sample spacing, in metres")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--z-scale", args->z_scale, "A PNG heightmap's height for its brightest value")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--geographic", args->geographic,
                  "An ESRI grid's cell size is in degrees (yes), metres (no), or guessed (auto:\n"
                  "degrees when cells are at most one arc-minute and the grid lies on the globe)")
      ->check(CLI::IsMember({"auto", "yes", "no"}))
      ->capture_default_str();
  cmd->add_option("--stats", args->stats,
                  "Print statistics; 'json': the last line of standard output is one JSON object\n"
                  "(vertices, triangles, max_error and rms_error over every sample, 3D angles)")
      ->check(CLI::IsMember({"json"}));
  add_record_option(*cmd, args->record);
  cmd->add_option("--tile", args->tile,
                  "Approximate in tiles of N x N samples (with --max-error), neighbours sharing a\n"
                  "row or column of samples and their border vertices (no cracks): for grids\n"
                  "bigger than memory. An .asc grid is streamed; peak memory is about\n"
                  "4 x N x COLUMNS bytes for the N rows held, plus 5 x N^2 bytes and 200 bytes a\n"
                  "TIN vertex for one tile (a .png is decoded whole first). With -o OUT.EXT (.obj,\n"
                  ".off, .ply) tile R,C goes to OUT.rR-cC.EXT, in the grid's metres; files appear\n"
                  "once the whole grid has been read. meshstep terrain-join joins them");
  cmd->add_option("--tile-index", args->tile_index,
                  "With --tile: only tile R,C (R counts rows of tiles from the south, C columns\n"
                  "from the west), the same file as the run of every tile writes; the grid is\n"
                  "still read whole, keeping N x N samples");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors (and --stats)");
  cmd->add_flag("-v,--verbose", args->verbose, "Print progress and timings");
  cmd->footer(
      "Example: meshstep terrain volcano.asc --max-error 0.5% -o volcano.obj\n"
      "         meshstep terrain big.asc --tile 1000 --max-error 0.1% -o tiles/big.ply");
  return {cmd, [args] { return run_terrain(*args); }};
}

}  // namespace meshstep::app
