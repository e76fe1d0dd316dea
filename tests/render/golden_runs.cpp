#include "golden_runs.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <filesystem>
#include <map>
#include <memory>

namespace meshstep::golden {
namespace {

namespace fs = std::filesystem;

const fs::path& run_folder() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("meshstep_golden_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

// Removes the folder when the test process ends.
struct FolderCleanup {
  ~FolderCleanup() {
    std::error_code ec;
    fs::remove_all(run_folder(), ec);
  }
};

}  // namespace

std::string asset(const std::string& name) { return std::string(MESHSTEP_ASSETS) + "/examples/" + name; }

const replay::LogReader* lesson_run(const std::string& arguments) {
  static std::map<std::string, std::unique_ptr<replay::LogReader>> runs;
  static FolderCleanup cleanup;
  if (auto found = runs.find(arguments); found != runs.end()) return found->second.get();
  const std::string log = (run_folder() / ("run" + std::to_string(runs.size()) + ".mslog")).string();
  const std::string command = std::string(MESHSTEP_BINARY) + " refine " + asset("lesson.poly") + " " + arguments +
                              " --record " + log + " --no-output -q";
  const int status = std::system(command.c_str());
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    ADD_FAILURE() << "recording failed: " << command;
    return nullptr;
  }
  return runs.emplace(arguments, std::make_unique<replay::LogReader>(log)).first->second.get();
}

const replay::LogReader* terrain_run(const std::string& arguments) {
  static std::map<std::string, std::unique_ptr<replay::LogReader>> runs;
  static FolderCleanup cleanup;
  if (auto found = runs.find(arguments); found != runs.end()) return found->second.get();
  const fs::path grid = run_folder() / "hills.asc";
  if (!fs::exists(grid)) {
    std::ofstream out(grid);
    out << "ncols 33\nnrows 25\nxllcorner 0\nyllcorner 0\ncellsize 10\n";
    for (int row = 0; row < 25; ++row) {
      for (int i = 0; i < 33; ++i) {
        const double x = i - 20.0, y = row - 12.0, r = std::hypot(x, y);
        out << 40.0 + 30.0 * std::exp(-(r - 5.0) * (r - 5.0) / 8.0) + 6.0 * std::sin(0.35 * i) << ' ';
      }
      out << '\n';
    }
  }
  const std::string log = (run_folder() / ("terrain" + std::to_string(runs.size()) + ".mslog")).string();
  const std::string command =
      std::string(MESHSTEP_BINARY) + " terrain " + grid.string() + " " + arguments + " --record " + log + " -q";
  const int status = std::system(command.c_str());
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    ADD_FAILURE() << "recording failed: " << command;
    return nullptr;
  }
  return runs.emplace(arguments, std::make_unique<replay::LogReader>(log)).first->second.get();
}

}  // namespace meshstep::golden
