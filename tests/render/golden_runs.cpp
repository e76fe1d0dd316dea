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

namespace {

// An ESRI ASCII grid in metres: 48 x 36 samples 10 m apart, heights about 100 to 150 (a peak,
// a slope and a ripple).
fs::path write_hills(const fs::path& dir) {
  constexpr int kColumns = 48, kRows = 36;
  const fs::path path = dir / "hills.asc";
  std::ofstream out(path);
  out << "ncols " << kColumns << "\nnrows " << kRows << "\nxllcorner 0\nyllcorner 0\ncellsize 10\n"
      << "NODATA_value -9999\n";
  for (int j = 0; j < kRows; ++j) {
    for (int i = 0; i < kColumns; ++i) {
      const double peak = 25.0 * std::exp(-((i - 30) * (i - 30) + (j - 12) * (j - 12)) / 60.0);
      const double ripple = 8.0 * std::sin(i * 0.35) * std::cos(j * 0.3);
      out << std::round(100.0 * (100.0 + peak + ripple + 0.5 * i)) / 100.0 << ' ';
    }
    out << '\n';
  }
  return path;
}

}  // namespace

const replay::LogReader* terrain_run(const std::string& arguments) {
  static std::map<std::string, std::unique_ptr<replay::LogReader>> runs;
  static FolderCleanup cleanup;
  static const fs::path grid = write_hills(run_folder());
  if (auto found = runs.find(arguments); found != runs.end()) return found->second.get();
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
