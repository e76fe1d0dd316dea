#include "common/tour_run.hpp"

#include <fcntl.h>
#include <cerrno>
#include <spawn.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "meshstep/error.hpp"

extern char** environ;

namespace meshstep::app {

namespace fs = std::filesystem;

std::vector<std::string> tour_run_arguments(const teach::Tour& tour, const std::string& program, const std::string& log,
                                            const std::string& scratch) {
  std::vector<std::string> args = {program};
  const auto words_of = [&](const Operation& op) {
    // The operation's printed words, less its first ("refine", "triangulate").
    std::istringstream words(print_operation(op));
    std::string word;
    words >> word;
    while (words >> word) args.push_back(word);
  };
  if (!tour.recipe.empty()) {
    // A recipe's run writes its mesh: into the scratch folder, which goes with the tour.
    args.insert(args.end(), {"run", tour.recipe, tour.input, "-o", scratch + "/mesh"});
  } else if (tour.operations.empty()) {
    args.insert(args.end(), {"triangulate", tour.input, "--no-output"});
  } else {
    const Operation& op = tour.operations.front();
    args.insert(args.end(), {op.kind == OperationKind::refine ? "refine" : "triangulate", tour.input, "--no-output"});
    words_of(op);
  }
  args.insert(args.end(), {"--record", log, "-q"});
  return args;
}

ScratchFolder::ScratchFolder() {
  std::string pattern = (fs::temp_directory_path() / "meshstep_tour_XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw InputError("cannot make a temporary folder for the tour's run");
  path_ = pattern;
}

ScratchFolder::~ScratchFolder() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::string record_tour_run(const teach::Tour& tour, const std::string& program, const ScratchFolder& scratch) {
  const std::string log = scratch.file("run.mslog"), said = scratch.file("run.messages");
  std::vector<std::string> args = tour_run_arguments(tour, program, log, scratch.path());
  std::vector<char*> argv;
  for (std::string& s : args) argv.push_back(s.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, 2, said.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid = -1;
  const int failed = ::posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  const auto line = static_cast<std::size_t>(tour.run_line);
  if (failed != 0) throw InputError(tour.path, line, "cannot start " + program + " to record the tour's run");
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream in(said);
    std::stringstream text;
    text << in.rdbuf();
    std::string words = text.str();
    while (!words.empty() && (words.back() == '\n' || words.back() == '\r')) words.pop_back();
    throw InputError(tour.path, line, "its run failed" + (words.empty() ? std::string() : ": " + words));
  }
  return log;
}

}  // namespace meshstep::app
