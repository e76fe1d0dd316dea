// meshstep run RECIPE INPUT: the operations of a recipe file, one after the other on the same
// mesh in one process (planar_refine.hpp). A recipe line is an operation in the command
// line's own words (run_spec.hpp); every line is read and checked before any work.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "console.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "planar_refine.hpp"
#include "recipe_file.hpp"
#include "record_option.hpp"

namespace meshstep::app {
namespace {

struct RunArgs {
  std::string recipe, input, prefix, record, stats, max_memory, ds, insertion;
  bool quiet = false, verbose = false;
};

int run_recipe(const RunArgs& args) {
  if (io::is_surface(args.input)) {
    print_error(args.input + ": a recipe refines a planar input (.poly, .node or a mesh PREFIX), not a 3D surface");
    return kExitUsage;
  }
  std::optional<Recipe> recipe = read_recipe_file(args.recipe, args.ds, args.insertion);
  if (!recipe) return kExitBadInput;
  PlanarRefineJob job;
  job.input = args.input;
  job.prefix = args.prefix;
  job.record = args.record;
  job.stats = args.stats;
  job.max_memory = args.max_memory;
  job.verbosity = args.quiet ? Verbosity::quiet : args.verbose ? Verbosity::verbose : Verbosity::normal;
  job.operations = std::move(recipe->operations);
  job.origins = std::move(recipe->origins);
  job.recipe = args.recipe;
  job.refusal_status = kExitBadInput;
  return run_planar_refine(job);
}

}  // namespace

Command add_run_command(CLI::App& parent) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "run",
      "Run a recipe: the operations of RECIPE, one per line, one after the other on the same\n"
      "mesh (the first refines INPUT, each next one the mesh so far). A line is an operation\n"
      "in the command line's words, e.g. 'refine --algorithm lepp-centroid --min-angle 25'\n"
      "or 'refine --max-area 2e-5 --region 0.2,-0.8,0.45,-0.5'; '#' starts a comment. Every\n"
      "line is checked before any work (docs/recipes.md).");
  cmd->add_option("RECIPE", args->recipe, "The recipe file")->required();
  cmd->add_option("INPUT", args->input, "Input .poly, .node, .geojson or .wkt file, or a mesh PREFIX to refine again")->required();
  cmd->add_option("-o,--output", args->prefix,
                  "Output prefix: writes PREFIX.node, PREFIX.ele, PREFIX.poly\n"
                  "(default: INPUT without extension plus .1, as refine does);\n"
                  "or one file OUT.msh, .vtu, .obj, .off, .ply or .stl in that format (meshstep list)");
  add_record_option(*cmd, args->record);
  cmd->add_option("--stats", args->stats, "Print statistics; 'json': as refine's, the last line of standard output")
      ->check(CLI::IsMember({"json"}));
  cmd->add_option("--ds", args->ds, "Mesh data structure of every operation: tds or dcel")
      ->check(CLI::IsMember({"tds", "dcel"}));
  cmd->add_option("--insertion", args->insertion, "Point insertion of every operation: flip, cavity or bisection")
      ->check(CLI::IsMember({"flip", "cavity", "bisection"}));
  cmd->add_option("--max-memory", args->max_memory,
                  "Stop before the run takes more memory than SIZE (8G, 500M, ...; none: no\n"
                  "budget). Default: a quarter of this machine's memory")
      ->type_name("SIZE");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors (and --stats)");
  cmd->add_flag("-v,--verbose", args->verbose, "Also print refinement counts, timings and the record summary");
  cmd->footer(
      "Example: meshstep run chain.recipe assets/examples/plate.poly -o plate_chain\n"
      "Exit status: 0 done, 1 bad input or a recipe line that cannot run (RECIPE:LINE: what\n"
      "is wrong; nothing is written), 2 usage error.");
  return {cmd, [args] { return run_recipe(*args); }};
}

}  // namespace meshstep::app
