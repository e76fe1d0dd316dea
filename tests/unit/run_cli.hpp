// Running the built `meshstep` binary from a test: its exit status and what it printed.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "temp_dir.hpp"

namespace meshstep::testing {

struct CommandResult {
  int status = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs the meshstep binary with `args` (already shell-quoted where needed); its standard
// output and error go through files in `dir`.
// The --stats json line: the last line of standard output.
inline std::string stats_line(const std::string& out) {
  const std::string trimmed = out.substr(0, out.find_last_not_of('\n') + 1);
  return trimmed.substr(trimmed.rfind('\n') + 1);
}

// The raw text of "key"'s value in a one-line JSON object, up to the next ',' or '}' ("" if
// absent; a string keeps its quotes).
inline std::string json_field(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  if (at == std::string::npos) return "";
  const auto start = at + key.size() + 3;
  return json.substr(start, json.find_first_of(",}", start) - start);
}

inline CommandResult run_meshstep(const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command =
      std::string(MESHSTEP_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(command.c_str());
  CommandResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// The fixture of a test that runs the meshstep binary: a scratch folder of its own, removed
// afterwards, whose name holds the process id and a random number (TempDir), so that two
// runs of the suite at once (two worktrees, ctest -j) never write into each other's files.
class CliTest : public ::testing::Test {
 protected:
  explicit CliTest(const std::string& prefix = "meshstep_cli_") : dir_(prefix) {}

  // meshstep ARGS (shell-quoted where needed), its output through files in the folder.
  CommandResult meshstep(const std::string& args) const { return run_meshstep(args, dir_.path()); }
  // A file in the folder written with `text`: its path.
  std::string write(const std::string& name, const std::string& text) const { return dir_.write(name, text); }
  // The path of `name` in the folder.
  std::string file(const std::string& name) const { return dir_.file(name); }

  TempDir dir_;
};

// Whether ffmpeg and ffprobe are installed and start. An installed ffmpeg can still fail to
// start: CI once had one that could not load libblas.so.3. The video tests skip then, saying so.
inline bool ffmpeg_works() {
  return std::system("ffmpeg -hide_banner -version >/dev/null 2>&1") == 0 &&
         std::system("ffprobe -hide_banner -version >/dev/null 2>&1") == 0;
}

}  // namespace meshstep::testing
