#include "export_job.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>
#include <vector>

#include "sibling_program.hpp"

extern char** environ;

namespace meshstep::viewer {

namespace {

namespace fs = std::filesystem;


}  // namespace

std::string export_name(const std::string& log_path, unsigned long long step, const char* what, const char* extension) {
  const fs::path log(log_path);
  const fs::path folder = log.has_parent_path() ? log.parent_path() : fs::path(".");
  return (folder / (log.stem().string() + "_" + what + std::to_string(step) + extension)).string();
}

ExportJob::ExportJob(std::string meshstep) : meshstep_(meshstep.empty() ? sibling_program("meshstep") : std::move(meshstep)) {}

ExportJob::~ExportJob() {
  if (pid_ > 0) {
    ::kill(pid_, SIGTERM);  // meshstep export removes its temporary file on the way out
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
}

bool ExportJob::start(const std::string& log, const std::string& out, unsigned long long from, unsigned long long to) {
  if (running()) return false;
  std::vector<std::string> args = {meshstep_,          "export", log,   "--video", out, "--every", "step",
                                   "--from",           std::to_string(from), "--to", std::to_string(to), "-q"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int error = ::posix_spawn(&pid_, argv[0], nullptr, nullptr, argv.data(), environ);
  if (error != 0) {
    pid_ = -1;
    status_ = "failed: cannot run " + args[0] + " (" + std::strerror(error) + ")";
    return false;
  }
  out_ = out;
  status_ = "writing " + out + " ...";
  return true;
}

bool ExportJob::running() {
  if (pid_ <= 0) return false;
  int status = 0;
  const pid_t done = ::waitpid(pid_, &status, WNOHANG);
  if (done == 0) return true;
  pid_ = -1;
  const bool ok = done > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  status_ = ok ? "wrote " + out_ : "failed: meshstep export ended with an error (see the terminal)";
  return false;
}

}  // namespace meshstep::viewer
