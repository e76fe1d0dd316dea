// The subcommands of `meshstep`: each registers its options on the parent CLI11 app and
// returns the function that runs it once the command line is parsed.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace meshstep::app {

// Exit statuses: part of the command-line contract.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;  // bad input file or a failed check
inline constexpr int kExitUsage = 2;

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

Command add_triangulate_command(CLI::App& parent);
Command add_check_command(CLI::App& parent);
Command add_log_command(CLI::App& parent);
Command add_refine_command(CLI::App& parent);
Command add_run_command(CLI::App& parent);
Command add_compare_command(CLI::App& parent);
Command add_list_command(CLI::App& parent);
Command add_render_command(CLI::App& parent);
Command add_export_command(CLI::App& parent);
Command add_view_command(CLI::App& parent);
Command add_explain_command(CLI::App& parent);
Command add_terrain_command(CLI::App& parent);
Command add_terrain_join_command(CLI::App& parent);

}  // namespace meshstep::app
