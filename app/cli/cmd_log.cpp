// meshstep log: look into a replay log (info, dump, mesh, verify, check).
#include "cmd_log.hpp"

namespace meshstep::app {

Command add_log_command(CLI::App& parent) {
  CLI::App* cmd = parent.add_subcommand(
      "log",
      "Inspect a replay log written with --record: its header and counts (info), its events\n"
      "(dump), the mesh after any step (mesh), a full consistency check (verify), and the\n"
      "mesh checked at every step, with the first step that breaks it (check).");
  cmd->require_subcommand(1);
  cmd->footer("Example: meshstep triangulate assets/examples/plate.poly --record plate.mslog\n"
              "         meshstep log info plate.mslog");
  std::vector<Command> subcommands = {add_log_info_command(*cmd), add_log_dump_command(*cmd),
                                      add_log_mesh_command(*cmd), add_log_verify_command(*cmd),
                                      add_log_check_command(*cmd)};
  return {cmd, [subcommands] {
            for (const Command& c : subcommands)
              if (c.app->parsed()) return c.run();
            return kExitUsage;
          }};
}

}  // namespace meshstep::app
