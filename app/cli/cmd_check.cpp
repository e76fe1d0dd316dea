// meshstep check: an independent validity check of a mesh written in Triangle's formats.
#include <cstdio>
#include <optional>
#include <string>

#include "command.hpp"
#include "console.hpp"
#include "meshstep/check/mesh_check.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "common/output_prefix.hpp"
#include "meshstep/io/formats.hpp"

namespace meshstep::app {
namespace {

struct CheckArgs {
  std::string prefix;
  std::string poly;
  bool no_delaunay = false;
  bool quiet = false;
};

int run_check(const CheckArgs& args) {
  // Accept "mesh.1" as well as "mesh.1.node" / "mesh.1.ele".
  const std::string prefix = io::mesh_prefix_of(args.prefix);
  const Verbosity verbosity = args.quiet ? Verbosity::quiet : Verbosity::normal;
  std::vector<std::string> warnings;
  TriMesh mesh;
  std::optional<Pslg> input;
  try {
    mesh = io::read_mesh(prefix, &warnings);
    if (!args.poly.empty()) input = io::read_pslg(args.poly, &warnings);
  } catch (const InputError& e) {
    print_error(e.what());
    return kExitBadInput;
  }
  for (const std::string& w : warnings) print_warning(verbosity, w);
  CheckOptions options;
  options.delaunay = !args.no_delaunay;
  const CheckReport report = check_mesh(mesh, input ? &*input : nullptr, options);
  if (report.ok) {
    if (verbosity != Verbosity::quiet)
      std::printf("%s: ok (%zu vertices, %zu triangles%s%s)\n", prefix.c_str(), mesh.points.size(),
                  mesh.triangles.size(), options.delaunay ? ", constrained Delaunay" : "",
                  input ? ", covers the input" : "");
    return kExitOk;
  }
  std::fprintf(stderr, "%s: INVALID: %zu problems\n", prefix.c_str(), report.problem_count);
  for (const std::string& p : report.problems) std::fprintf(stderr, "  %s\n", p.c_str());
  if (report.problem_count > report.problems.size())
    std::fprintf(stderr, "  ... and %zu more\n", report.problem_count - report.problems.size());
  return kExitBadInput;
}

}  // namespace

Command add_check_command(CLI::App& parent) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "check",
      "Check a mesh (PREFIX.node + PREFIX.ele, and PREFIX.poly when present): orientation,\n"
      "manifold edges, no overlaps, constrained Delaunay property; with --poly, also that\n"
      "every input vertex is present and every input segment is covered by mesh edges.\n"
      "Exit 0 when valid, 1 with the list of problems otherwise.");
  cmd->add_option("PREFIX", args->prefix, "Mesh prefix (e.g. box.1 for box.1.node/box.1.ele)")
      ->required();
  cmd->add_option("--poly", args->poly, "The input .poly or .node the mesh was made from");
  cmd->add_flag("--no-delaunay", args->no_delaunay,
                "Skip the constrained Delaunay test (for meshes that are not meant to be)");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing when the mesh is valid");
  return {cmd, [args] { return run_check(*args); }};
}

}  // namespace meshstep::app
