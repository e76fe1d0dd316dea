// meshstep refine: Delaunay refinement of a .poly PSLG (or a .node point set) into a quality
// mesh, by one of the registered algorithms (refine/registry.hpp).
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "command.hpp"
#include "console.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "operation_options.hpp"
#include "planar_output_options.hpp"
#include "planar_refine.hpp"
#include "record_option.hpp"
#include "refine_surface.hpp"

namespace meshstep::app {
namespace {

struct RefineArgs {
  // The refinement's own options (algorithm, bounds, parts), from the registry's records.
  std::unique_ptr<OperationOptions> operation;
  PlanarOutputOptions out;  // INPUT, -o, --record, --stats, ... (shared with `run`)
};

// A 3D surface goes to longest-edge bisection in 3D; only its own options apply.
int refine_surface(const RefineArgs& args, const Operation& op) {
  if (op.region) {
    print_error("--region, --region-polygon and --region-poly limit a planar refinement: they do not apply to a 3D surface");
    return kExitUsage;
  }
  for (const std::string& name : args.operation->given()) {
    const ParameterInfo* p = find_parameter(std::string_view(name).substr(2));
    if (p && p->bound && name != "--size" && name != "--max-area") {
      print_error(name + " does not apply to a 3D surface: it takes --size L, --max-area A and --max-triangles N");
      return kExitUsage;
    }
  }
  SurfaceRefineArgs surface;
  const PlanarRefineJob job = args.out.read();
  surface.input = job.input;
  surface.output = job.prefix;
  surface.operation = op;
  if (op.size && !size_length(op)) {
    print_error("--size: a 3D surface takes a length, not '" + *op.size + "'");
    return kExitUsage;
  }
  surface.max_edge = size_length(op).value_or(0.0);
  surface.stats = job.stats;
  surface.no_output = job.no_output;
  surface.quiet = job.verbosity == Verbosity::quiet;
  surface.record = job.record;
  return run_refine_surface(surface);
}

int run_refine(const RefineArgs& args) {
  const std::optional<Operation> given = args.operation->operation();
  if (!given) return kExitUsage;
  if (io::is_surface(args.out.job.input)) return refine_surface(args, *given);
  if (given->flip_dihedral) {
    print_error("--flip-dihedral flips the edges of a 3D surface (.off, .obj, .ply, .stl), not of a planar mesh");
    return kExitUsage;
  }
  PlanarRefineJob job = args.out.read();
  job.operations = {*given};
  return run_planar_refine(job);
}

}  // namespace

Command add_refine_command(CLI::App& parent) {
  auto args = std::make_shared<RefineArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "refine",
      "Delaunay refinement: triangulate a .poly PSLG (or a .node point set), then insert Steiner\n"
      "vertices until every triangle meets the bounds (see 'meshstep list' for the algorithms).\n"
      "Without any bound (--min-angle, --max-angle, --max-aspect, --max-area, --size) the\n"
      "algorithm's default applies: a minimum angle of 20.7 degrees, an aspect ratio of 2.83\n"
      "for lepp-aspect; lepp-bisection and midpoint-area need --max-area or --size. INPUT may\n"
      "also be a mesh PREFIX (PREFIX.node + PREFIX.ele [+ PREFIX.area]) to refine again.");
  cmd->add_option("INPUT", args->out.job.input, "Input .poly or .node file (Triangle's formats), .geojson or .wkt\n"
                  "polygons (holes as holes), or a mesh PREFIX\n"
                  "(PREFIX.node + PREFIX.ele, optionally PREFIX.area) to refine again, as Triangle's -r;\n"
                  "or a 3D surface (.off, .obj, .ply, .stl): --algorithm lepp-bisection with --size L\n"
                  "and/or --max-area A, edges and areas in 3D; -o names the output surface file")->required();

  args->operation = std::make_unique<OperationOptions>(*cmd, OperationKind::refine);
  add_planar_output_options(*cmd, args->out);
  cmd->footer(
      "Example: meshstep refine assets/examples/plate.poly --algorithm offcenter --min-angle 30 -o plate_q\n"
      "Exit status: 0 done (even if some triangles miss the bounds; see the summary),\n"
      "1 bad input or bounds out of range, 2 usage error.");
  return {cmd, [args] { return run_refine(*args); }};
}

}  // namespace meshstep::app
