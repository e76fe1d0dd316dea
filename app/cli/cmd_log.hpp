// The subcommands of `meshstep log`, one file each.
#pragma once

#include <string>

#include "command.hpp"
#include "console.hpp"
#include "meshstep/error.hpp"

namespace meshstep::app {

Command add_log_info_command(CLI::App& log);
Command add_log_dump_command(CLI::App& log);
Command add_log_mesh_command(CLI::App& log);
Command add_log_verify_command(CLI::App& log);
Command add_log_check_command(CLI::App& log);

// Opening a log and reporting failure the same way everywhere.
template <class F>
int with_log_errors(F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    print_error(e.what());
    return kExitBadInput;
  }
}

}  // namespace meshstep::app
