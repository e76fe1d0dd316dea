// What the tests that drive the viewer program share: running a command (its status and
// everything it printed), running the viewer on a log with a script in a mode, reading a
// file whole, and reading the state file's fields.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer::testing {

struct Result {
  int status = -1;
  std::string output;  // standard output and error together
};

// Under the sanitizers, the programs these tests start are not leak-checked at their exit:
// LeakSanitizer's stop-the-world crashed there ("Tracer caught signal 11") among Mesa's
// llvmpipe threads, in 2 runs of 2 of the four-canvas test and 3 of 3 of the workbench's,
// failing tests whose checks had all passed. Their memory errors are still caught, and the
// unit and command-line tests keep the leak check. (The test binary's own options are read
// at its start: this changes only what its children inherit.)
inline void children_skip_leak_check() {
  if (MESHSTEP_VIEW_COUNTS_NEW) return;  // not a sanitizer build
  static const bool done = [] {
    const char* given = std::getenv("ASAN_OPTIONS");
    const std::string options = given && *given ? std::string(given) + ":detect_leaks=0" : "detect_leaks=0";
    return ::setenv("ASAN_OPTIONS", options.c_str(), 1) == 0;
  }();
  (void)done;
}

inline Result run(const std::string& command) {
  children_skip_leak_check();
  Result r;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.output.append(buf, n);
  const int status = ::pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline bool has(const std::string& text, const std::string& part);

// Runs meshstep-view (VIEWER) on LOG with SCRIPT, written to DIR/script.txt, at SIZE
// ("1024x640"), in MODE: "egl" and "osmesa" off screen, "window" under xvfb-run. Status 77
// when the mode cannot be had here, the output saying why (VIEW_OR_SKIP skips then).
inline Result view_log(const std::string& viewer, const std::string& log, const std::filesystem::path& dir,
                       const std::string& mode, const std::string& size, const std::string& script,
                       const std::string& extra = "") {
  const std::filesystem::path file = dir / "script.txt";
  std::ofstream(file) << script;
  std::string command = viewer + " " + log + " --window " + size + " -q --script " + file.string() + " " + extra;
  if (mode == "window") {
    if (run("command -v xvfb-run").status != 0) return {77, "xvfb-run is not installed (Debian package xvfb)"};
    command = "xvfb-run -a -s '-screen 0 1280x800x24' " + command;
  } else {
    command += " --offscreen --gl " + mode;
  }
  Result r = run(command);
  if (r.status != 0 && has(r.output, "cannot open a window or draw")) return {77, r.output};
  return r;
}

// In a fixture whose view(script, extra...) calls view_log: the run's result, the test
// skipped when the mode is not available, failed when the viewer did.
#define VIEW_OR_SKIP(result, script, ...)                 \
  const Result result = view(script, ##__VA_ARGS__);      \
  if (result.status == 77) GTEST_SKIP() << result.output; \
  ASSERT_EQ(result.status, 0) << result.output

// A test of the viewer program on one recorded run, per mode (the parameter: "egl",
// "osmesa", "window"): a folder of its own for scripts and outputs, and view(). A fixture
// derives, names its folder and size, and sets log_ in SetUp (after this SetUp).
class ScriptedViewer : public ::testing::TestWithParam<std::string> {
 protected:
  ScriptedViewer(std::string folder, std::string size) : folder_(std::move(folder)), size_(std::move(size)) {}
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / (folder_ + "_" + std::to_string(::getpid()) + "_" + GetParam());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  // Runs the viewer on log_ with this script, in the mode of the parameter (view_log).
  Result view(const std::string& script, const std::string& extra = "") {
    return view_log(MESHSTEP_VIEW_BINARY, log_->path(), dir_, GetParam(), size_, script, extra);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
  const replay::LogReader* log_ = nullptr;

 private:
  std::string folder_, size_;
};

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The number after "KEY": in the state file (one field per line); -1 when it is not there.
inline long long field(const std::string& json, const std::string& key) {
  const std::string tag = "\"" + key + "\": ";
  const auto at = json.find(tag);
  return at == std::string::npos ? -1 : std::atoll(json.c_str() + at + tag.size());
}

// The allocations column of a viewer's --frame-log (`# frame end_ms frame_ms allocations
// ...`), one entry a frame.
inline std::vector<unsigned long long> frame_allocations(const std::filesystem::path& frame_log) {
  std::ifstream in(frame_log);
  std::vector<unsigned long long> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    unsigned long long index = 0, count = 0;
    double end_ms = 0, frame_ms = 0;
    fields >> index >> end_ms >> frame_ms >> count;
    out.push_back(count);
  }
  return out;
}

}  // namespace meshstep::viewer::testing
