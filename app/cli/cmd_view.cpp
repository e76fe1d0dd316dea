// meshstep view: runs the viewer, meshstep-view, which lives beside this program. The
// viewer is a program of its own so that meshstep needs no GLFW, X11 or ImGui: the batch
// commands run on machines with no display.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "command.hpp"
#include "console.hpp"

namespace meshstep::app {

namespace {

std::string viewer_program() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("meshstep-view") : (self.parent_path() / "meshstep-view").string();
}

}  // namespace

Command add_view_command(CLI::App& parent) {
  CLI::App* cmd = parent.add_subcommand(
      "view",
      "Open the viewer (meshstep-view): scrub a recorded run forward and backward, see why each\n"
      "point went where it did, play it; or look at a mesh or an input. `meshstep view --help`\n"
      "lists its options and keys.");
  cmd->allow_extras();
  cmd->prefix_command();  // everything after `view` is the viewer's, --help included
  cmd->set_help_flag();
  return {cmd, [cmd] {
            const std::string program = viewer_program();
            std::vector<std::string> args = {program};
            for (const std::string& a : cmd->remaining()) args.push_back(a);
            std::vector<char*> argv;
            for (std::string& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            ::execv(program.c_str(), argv.data());
            print_error("meshstep view: cannot run " + program + " (" + std::strerror(errno) +
                        "); it is built with meshstep (target meshstep-view)");
            return kExitBadInput;
          }};
}

}  // namespace meshstep::app
