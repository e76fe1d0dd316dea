#include "open_input.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "common/scene_source.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/formats.hpp"
#include "live_run.hpp"


namespace meshstep::viewer {

namespace {

namespace fs = std::filesystem;

fs::path program_folder() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}


}  // namespace

Opener::~Opener() {
  std::error_code ec;
  for (const std::string& log : temporary_logs_) fs::remove(log, ec);
}

std::string Opener::temporary_log() {
  const std::string log = (fs::temp_directory_path() / ("meshstep-view-" + std::to_string(::getpid()) + "-" +
                                                        std::to_string(temporary_logs_.size()) + ".mslog"))
                              .string();
  temporary_logs_.push_back(log);
  return log;
}

std::unique_ptr<LiveRun> Opener::start_live(const std::string& input, const RefineOptions& refine,
                                            const std::string& backend) {
  return std::make_unique<LiveRun>(input, refine, temporary_log(), backend);
}

bool is_input(const std::string& path) { return io::is_planar_input(path); }

std::unique_ptr<Session> Opener::open(const std::string& path) {
  if (app::is_replay_log(path)) return Session::open_log(path);
  std::vector<std::string> warnings;
  app::SceneSource source = app::open_scene_source(path, &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "%s\n", w.c_str());
  if (source.mesh) return Session::still(std::move(*source.mesh), path);
  return Session::still(std::move(*source.input), path);
}

std::vector<Example> bundled_examples() {
  // Installed or built: the examples are found from the program's folder upward, else
  // from the source tree the program was built from.
  std::vector<fs::path> folders;
  for (fs::path p = program_folder(); !p.empty() && p != p.root_path(); p = p.parent_path())
    folders.push_back(p / "assets" / "examples");
#ifdef MESHSTEP_SOURCE_ASSETS
  folders.emplace_back(MESHSTEP_SOURCE_ASSETS "/examples");
#endif
  for (const fs::path& folder : folders) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) continue;
    std::vector<Example> out;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
      if (entry.path().extension() != ".poly") continue;
      Example e{entry.path().string(), ""};
      std::ifstream in(entry.path());
      for (std::string line; std::getline(in, line);)
        if (line.starts_with("#")) {
          e.description = line.substr(line.find_first_not_of("# ") == std::string::npos ? line.size()
                                                                                          : line.find_first_not_of("# "));
          break;
        }
      out.push_back(std::move(e));
    }
    std::sort(out.begin(), out.end(), [](const Example& a, const Example& b) { return a.path < b.path; });
    if (!out.empty()) return out;
  }
  return {};
}

}  // namespace meshstep::viewer
