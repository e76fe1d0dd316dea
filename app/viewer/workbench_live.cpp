// The workbench's live re-meshing (workbench.hpp: goes_live): the input and the recipe as
// files, the command that runs them (the one a person would type: `meshstep run RECIPE
// INPUT`), and its end read back as remesh() reads its own run's.
#include <filesystem>

#include "meshstep/error.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/io/write_pslg.hpp"
#include "workbench.hpp"

namespace meshstep::viewer {

namespace fs = std::filesystem;

bool Workbench::goes_live() const {
  const std::size_t n = editor_.input().points.size();
  if (n == 0) return false;  // nothing to mesh: remesh() shows the empty canvas at once
  return cpu_ms_ > kLiveCpuMs || last_vertices_ > kLiveVertices || n > kLiveVertices;
}

Workbench::LiveCommand Workbench::live_command(const std::string& program) {
  made_revision_ = editor_.revision() + recipe_revision_;
  ++remeshes_;
  ++live_runs_;
  notices_.clear();
  const std::string poly = temporary("input.poly"), recipe = temporary("recipe.txt");
  LiveCommand c;
  c.log = temporary("run-" + std::to_string(remeshes_) + ".mslog");
  io::write_pslg(poly, editor_.input());
  bool any = false;
  for (std::size_t i = 0; i < recipe_.size(); ++i) any = any || enabled_[i];
  if (any) {
    io::write_file_atomically(recipe, recipe_text());
    c.args = {program, "run", recipe, poly};
  } else {
    c.args = {program, "triangulate", poly};
  }
  for (const char* word : {"--record", c.log.c_str(), "--no-output", "-q", "--stats", "json"}) c.args.emplace_back(word);
  return c;
}

std::unique_ptr<Session> Workbench::finish_live(const std::string& log, bool succeeded, const std::string& messages,
                                                const std::string& output, double cpu_seconds, double wall_ms,
                                                std::unique_ptr<Session> opened, const std::string& open_error) {
  notices_.clear();
  cpu_ms_ = 1e3 * cpu_seconds;
  remesh_ms_ = wall_ms;
  const int first_index = editor_.input().first_index;
  std::unique_ptr<Session> session;
  if (succeeded) {
    if (!opened) {
      notices_.push_back({ElementRef{}, open_error.empty() ? log + ": the run's log could not be read" : open_error, true});
      return nullptr;
    }
    session = shown(std::move(opened), log);
    last_vertices_ = session->log() ? session->log()->vertices().size() : 0;
    // The triangles from its --stats line ("triangles":N).
    if (const auto at = output.find("\"triangles\":"); at != std::string::npos)
      mesh_triangles_ = std::strtoull(output.c_str() + at + 12, nullptr, 10);
    return session;
  }
  // Refused: the program's first line, less the temporary input's "FILE:LINE: " (the
  // element it names is drawn instead).
  std::string said = messages.substr(0, messages.find('\n'));
  const std::string poly = temporary("input.poly");
  if (said.starts_with(poly + ":")) {
    const std::size_t at = said.find(": ", poly.size());
    if (at != std::string::npos) said = said.substr(at + 2);
  }
  if (said.empty()) said = "the re-meshing failed (meshstep said nothing)";
  notices_.push_back({element_named(said, first_index), said, true});
  std::error_code ec;
  fs::remove(log, ec);
  fs::remove(log + ".partial", ec);
  return nullptr;
}

}  // namespace meshstep::viewer
