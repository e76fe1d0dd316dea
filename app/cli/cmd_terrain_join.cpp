// meshstep terrain-join: the tiles of `meshstep terrain --tile` welded into one surface, and
// checked for cracks (terrain/tile_join.hpp).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "console.hpp"
#include "refuse_overwrites.hpp"
#include "json_line.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/terrain/tile_join.hpp"

namespace meshstep::app {
namespace {

struct TerrainJoinArgs {
  std::vector<std::string> tiles;
  std::string output;
  std::string stats;
  bool quiet = false;
  bool verbose = false;
};

void print_join_stats(const TerrainJoinArgs& args, const io::Surface& joined, std::size_t welded,
                      const terrain::TileJoinCheck& check) {
  JsonLine stats;
  stats.field("tiles", args.tiles.size())
      .field("vertices", joined.vertices.size())
      .field("welded", welded)
      .field("triangles", joined.triangles.size())
      .field("boundary_loops", check.surface.boundary_loops)
      .field("boundary_edges", check.surface.boundary_edges)
      .field("cracks", check.cracks)
      .field("non_manifold_edges", check.surface.non_manifold_edges)
      .field("inconsistent_edges", check.surface.inconsistent_edges)
      .field("area", check.area)
      .field("rectangle_area", check.rectangle_area)
      .field("ok", check.ok());
  std::printf("%s\n", stats.str().c_str());
}

int run_terrain_join(const TerrainJoinArgs& args) {
  const Verbosity verbosity =
      args.quiet ? Verbosity::quiet : args.verbose ? Verbosity::verbose : Verbosity::normal;
  FileRoles files;
  for (const std::string& tile : args.tiles) files.reads(tile);
  if (const int refused = refuse_overwrites(files.writes("-o", args.output, "output"))) return refused;
  std::optional<io::SurfaceFormat> format;
  if (!args.output.empty()) {
    format = io::surface_format_for(args.output);
    if (!format) {
      print_error(args.output + ": unknown output format (use .obj, .off, .ply or .stl)");
      return kExitUsage;
    }
  }
  terrain::SurfaceWelder welder;
  for (const std::string& path : args.tiles) {
    try {
      print_progress(verbosity, "reading " + path);
      welder.add(io::read_surface(path));
    } catch (const InputError& e) {
      print_error(input_error_text(path, e));
      return kExitBadInput;
    }
  }
  const terrain::TileJoinCheck check = terrain::check_joined_tiles(welder.surface());
  if (verbosity != Verbosity::quiet)
    std::printf("%zu tiles -> %zu vertices (%zu welded), %zu triangles; %s\n", args.tiles.size(),
                welder.surface().vertices.size(), welder.welded(), welder.surface().triangles.size(),
                terrain::describe(check).c_str());
  if (args.stats == "json") print_join_stats(args, welder.surface(), welder.welded(), check);
  if (!check.ok()) {
    // A joined terrain is one disc over the rectangle; anything else is a bug, or tiles of
    // different runs or grids, and is not written.
    print_error("the tiles do not join into one surface without cracks: " + terrain::describe(check) +
                (args.output.empty() ? "" : "; nothing written"));
    return kExitBadInput;
  }
  if (!args.output.empty()) {
    try {
      print_progress(verbosity, "writing " + args.output);
      io::write_surface(args.output, welder.surface(), *format);
    } catch (const InputError& e) {
      print_error(input_error_text(args.output, e));
      return kExitBadInput;
    }
  }
  return kExitOk;
}

}  // namespace

Command add_terrain_join_command(CLI::App& parent) {
  auto args = std::make_shared<TerrainJoinArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "terrain-join",
      "Join the tiles of 'meshstep terrain --tile' into one surface: vertices at exactly the\n"
      "same coordinates welded, then checked: one boundary loop round the rectangle, no crack\n"
      "(an edge of one triangle inside it), no non-manifold edge, the rectangle covered once.");
  cmd->add_option("TILES", args->tiles, "Every tile file of the run (.obj, .off, .ply), e.g. out.r*-c*.ply")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "Write the joined surface (.obj, .off, .ply, .stl); not written if the check fails");
  cmd->add_option("--stats", args->stats,
                  "'json': the last line of standard output is one JSON object (vertices, welded,\n"
                  "triangles, boundary_loops, cracks, area, ok)")
      ->check(CLI::IsMember({"json"}));
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors (and --stats)");
  cmd->add_flag("-v,--verbose", args->verbose, "Print progress");
  cmd->footer("Example: meshstep terrain-join tiles/big.r*-c*.ply -o big.ply\n"
              "Exit status 1 when the tiles do not join cleanly.");
  return {cmd, [args] { return run_terrain_join(*args); }};
}

}  // namespace meshstep::app
