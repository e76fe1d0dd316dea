#include "live_run.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "meshstep/error.hpp"
#include "sibling_program.hpp"

extern char** environ;

namespace meshstep::viewer {

std::vector<std::string> run_arguments(const std::string& input, const RefineOptions& refine, const std::string& log) {
  std::vector<std::string> args = {sibling_program("meshstep"), refine.any() ? "refine" : "triangulate", input,
                                   "--record", log, "--no-output", "-q"};
  if (!refine.operation) return args;
  // The operation in its printed words, less the leading "refine".
  std::istringstream words(print_operation(*refine.operation));
  std::string word;
  words >> word;
  while (words >> word) args.push_back(word);
  if (!refine.max_memory.empty()) args.insert(args.end(), {"--max-memory", refine.max_memory});
  return args;
}

LiveRun::LiveRun(const std::string& input, const RefineOptions& refine, std::string log, const std::string& backend)
    : LiveRun(run_arguments(input, refine, log), input, log, backend) {}

LiveRun::LiveRun(std::vector<std::string> args, std::string input, std::string log, const std::string& backend)
    : input_(std::move(input)),
      log_(std::move(log)),
      messages_file_(log_ + ".messages"),
      output_file_(log_ + ".out"),
      started_(std::chrono::steady_clock::now()) {
  command_ = "meshstep";
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--record") break;  // the rest is the viewer's business
    command_.append(" ").append(args[i]);
  }
  std::vector<char*> argv;
  for (std::string& s : args) argv.push_back(s.data());
  argv.push_back(nullptr);
  // Its messages go to a file of their own, shown in the window if the run fails.
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 2, messages_file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&files, 1, output_file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  const int failed = ::posix_spawn(&pid_, argv[0], &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (failed != 0) throw InputError(input_, 0, "cannot run " + args[0] + " to triangulate it");
  if (!backend.empty())
    preview_ = std::make_unique<CanvasWorker>(log_ + ".partial", backend, CanvasWorker::Follow::growing_log);
}

LiveRun::~LiveRun() {
  if (running()) {
    ::kill(pid_, SIGTERM);
    ::waitpid(pid_, nullptr, 0);
  }
  preview_.reset();
  std::error_code ec;
  std::filesystem::remove(messages_file_, ec);
  std::filesystem::remove(output_file_, ec);
}

bool LiveRun::running() {
  if (done_) return false;
  int status = 0;
  struct rusage usage {};
  const pid_t r = ::wait4(pid_, &status, WNOHANG, &usage);
  if (r == 0) return true;
  cpu_seconds_ = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                 1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  done_ = true;
  ended_ = std::chrono::steady_clock::now();
  status_ = r == pid_ && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return false;
}

void LiveRun::cancel() {
  if (!running()) return;
  cancelled_ = true;
  ::kill(pid_, SIGTERM);
  ::waitpid(pid_, nullptr, 0);
  done_ = true;
  ended_ = std::chrono::steady_clock::now();
  status_ = -1;
}

double LiveRun::seconds() const {
  return std::chrono::duration<double>((done_ ? ended_ : std::chrono::steady_clock::now()) - started_).count();
}

std::string LiveRun::output() const {
  std::ifstream in(output_file_);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string LiveRun::messages() const {
  std::ifstream in(messages_file_);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace meshstep::viewer
