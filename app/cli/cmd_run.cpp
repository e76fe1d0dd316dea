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
#include "planar_output_options.hpp"
#include "planar_refine.hpp"
#include "recipe_file.hpp"
#include "record_option.hpp"

namespace meshstep::app {
namespace {

struct RunArgs {
  std::string recipe, ds, insertion;
  PlanarOutputOptions out;  // INPUT, -o, --record, --stats, ... (shared with `refine`)
};

int run_recipe(const RunArgs& args) {
  if (io::is_surface(args.out.job.input)) {
    print_error(args.out.job.input + ": a recipe refines a planar input (.poly, .node or a mesh PREFIX), not a 3D surface");
    return kExitUsage;
  }
  std::optional<Recipe> recipe = read_recipe_file(args.recipe, args.ds, args.insertion);
  if (!recipe) return kExitBadInput;
  PlanarRefineJob job = args.out.read();
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
  cmd->add_option("INPUT", args->out.job.input, "Input .poly, .node, .geojson or .wkt file, or a mesh PREFIX to refine again")->required();
  cmd->add_option("--ds", args->ds, "Mesh data structure of every operation: tds or dcel")
      ->check(CLI::IsMember({"tds", "dcel"}));
  cmd->add_option("--insertion", args->insertion, "Point insertion of every operation: flip, cavity or bisection")
      ->check(CLI::IsMember({"flip", "cavity", "bisection"}));
  add_planar_output_options(*cmd, args->out);
  cmd->footer(
      "Example: meshstep run chain.recipe assets/examples/plate.poly -o plate_chain\n"
      "Exit status: 0 done, 1 bad input or a recipe line that cannot run (RECIPE:LINE: what\n"
      "is wrong; nothing is written), 2 usage error.");
  return {cmd, [args] { return run_recipe(*args); }};
}

}  // namespace meshstep::app
