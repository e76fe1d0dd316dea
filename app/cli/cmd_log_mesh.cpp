// meshstep log mesh: the mesh after K steps of a recorded run, in Triangle's formats, as the
// run itself writes its output (at the end: the run's own files).
#include <cstdio>
#include <memory>

#include "cmd_log.hpp"
#include "refuse_overwrites.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/replay/replay.hpp"
#include "mesh_output.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "common/output_prefix.hpp"

namespace meshstep::app {
namespace {

struct MeshArgs {
  std::string log;
  std::int64_t step = -1;
  std::string prefix;
};

int run_mesh(const MeshArgs& args) {
  const std::string label = args.step < 0 ? "end" : "step" + std::to_string(args.step);
  const std::string prefix = args.prefix.empty() ? strip_extension(args.log) + "." + label : args.prefix;
  const MeshOutput output = MeshOutput::named(prefix);
  FileRoles files;
  files.reads(args.log);
  output.add_to(files, args.prefix.empty() ? "" : "-o");
  if (const int refused = refuse_overwrites(files)) return refused;
  return with_log_errors([&] {
    const replay::LogReader log(args.log);
    if (!log.complete()) print_warning(Verbosity::normal, args.log + ": " + log.incomplete_reason());
    const std::uint64_t steps = log.step_count();
    if (const std::string refused = replay::step_refusal(log, "--step", args.step); !refused.empty()) {
      print_error(refused);
      return kExitUsage;
    }
    replay::Replay replay(log);
    if (args.step < 0) replay.seek_event(log.event_count());
    else replay.seek_step(static_cast<std::uint64_t>(args.step));
    const TriMesh mesh = replay.output_mesh();
    output.write(mesh);
    std::printf("%s: mesh after %llu of %llu steps (event %llu): %zu vertices, %zu triangles, written to %s\n",
                args.log.c_str(), static_cast<unsigned long long>(replay.completed_steps()),
                static_cast<unsigned long long>(steps), static_cast<unsigned long long>(replay.position()),
                mesh.points.size(), mesh.triangles.size(),
                (output.single_file() ? prefix : prefix + ".*").c_str());
    return kExitOk;
  });
}

}  // namespace

Command add_log_mesh_command(CLI::App& log) {
  auto args = std::make_shared<MeshArgs>();
  CLI::App* cmd = log.add_subcommand("mesh", "Write the mesh after K steps as PREFIX.node/.ele/.poly,\n"
                                                   "or as one file OUT.msh, .vtu, .obj, .off, .ply or .stl");
  cmd->add_option("LOG", args->log, "Replay log")->required();
  cmd->add_option("--step", args->step, "Number of steps K (0: before the first; -1: the end)")
      ->required();
  cmd->add_option("-o,--output", args->prefix, "Output prefix (default: LOG without extension plus .stepK), or one file\n"
                  "OUT.msh, .vtu, .obj, .off, .ply or .stl");
  return {cmd, [args] { return run_mesh(*args); }};
}

}  // namespace meshstep::app
