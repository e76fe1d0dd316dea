// Timing whole processes from a benchmark program: fork, exec, wait4. Shared by the
// programs that compare meshstep's command line with a peer's (terrain_table, triangle_compare).
#pragma once

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace meshstep::bench {

struct Process {
  int exit_status = -1;  // -1: killed by a signal, or could not start
  double ms = 0.0;       // wall clock
  double cpu_ms = 0.0;   // user + system
  double peak_mb = 0.0;
};

// Runs args[0] with stdout and stderr into files; wall clock from fork to wait4. The child's
// ru_maxrss is its own: checked on this machine (Linux 6.18), a parent holding 500 MB
// forks children whose ru_maxrss stays at 1 MB.
inline Process run_process(const std::vector<std::string>& args, const std::filesystem::path& out,
                           const std::filesystem::path& err) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::fflush(nullptr);
  Process p;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) return p;
  if (pid == 0) {
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (o < 0 || e < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0) ::_exit(126);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  if (::wait4(pid, &status, 0, &usage) != pid) return p;
  p.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const auto ms = [](const timeval& t) { return 1e3 * static_cast<double>(t.tv_sec) + 1e-3 * static_cast<double>(t.tv_usec); };
  p.cpu_ms = ms(usage.ru_utime) + ms(usage.ru_stime);
  p.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
  if (WIFEXITED(status)) p.exit_status = WEXITSTATUS(status);
  return p;
}

// The machine is shared: how busy it was, for the reader of the times.
inline std::string load_average() {
  std::string one, five, fifteen;
  std::ifstream("/proc/loadavg") >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

inline std::filesystem::path program_dir() { return std::filesystem::read_symlink("/proc/self/exe").parent_path(); }

}  // namespace meshstep::bench
