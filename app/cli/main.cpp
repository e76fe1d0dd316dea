// meshstep: the command-line front end. Parses the subcommand, runs it, and turns every
// failure into a message and an exit status (0 ok, 1 bad input or failed check, 2 usage).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <new>
#include <vector>

#include "command.hpp"
#include "console.hpp"
#include "render/leak_check.hpp"

namespace {

constexpr const char* kFooter =
    "Exit status: 0 success, 1 bad input or failed check, 2 usage error.\n"
    "Run 'meshstep COMMAND --help' for the options of one command.";

}  // namespace

int main(int argc, char** argv) {
  using namespace meshstep::app;
  meshstep::render::check_leaks_before_gl_in_this_program();
  CLI::App app{"meshstep " MESHSTEP_VERSION
               ": 2D Delaunay and constrained Delaunay triangulation, Delaunay\n"
               "refinement algorithms, terrain approximation, mesh checking, replay logs to\n"
               "step through them, and pictures and animations of any moment of a run.",
               "meshstep"};
  app.footer(kFooter);
  app.set_version_flag("--version", "meshstep " MESHSTEP_VERSION);
  app.require_subcommand(0, 1);
  std::vector<Command> commands = {add_triangulate_command(app), add_refine_command(app),
                                  add_run_command(app), add_compare_command(app),
                                  add_explain_command(app),
                                  add_check_command(app), add_list_command(app),
                                  add_log_command(app), add_render_command(app),
                                  add_export_command(app), add_view_command(app),
                                  add_terrain_command(app), add_terrain_join_command(app)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    print_error(e.what());
    std::fprintf(stderr, "Run 'meshstep --help' or 'meshstep COMMAND --help' for usage.\n");
    return kExitUsage;
  }

  for (const Command& command : commands) {
    if (!command.app->parsed()) continue;
    try {
      return command.run();
    } catch (const std::bad_alloc&) {
      print_error("out of memory");
      return kExitBadInput;
    } catch (const std::exception& e) {
      print_error(std::string("internal error: ") + e.what());
      return kExitBadInput;
    }
  }
  std::fputs(app.help().c_str(), stderr);
  return kExitUsage;
}
