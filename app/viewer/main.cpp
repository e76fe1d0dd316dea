// meshstep-view: the viewer (`meshstep view` runs it). See README.md, "The viewer".
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../scene_source.hpp"
#include "meshstep/error.hpp"
#include "render/gl_context.hpp"
#include "run.hpp"
#include "settings.hpp"

extern char** environ;

namespace {

using namespace meshstep;
namespace fs = std::filesystem;

constexpr int kExitUsage = 2, kExitInput = 1;

struct Args {
  std::string input;
  std::int64_t step = -1, event = -1;
  std::string script, size = "1280x800", gl = "auto";
  bool offscreen = false, quiet = false;
  std::string frame_log;
  // Refinement of an input, as `meshstep refine` takes them.
  std::string algorithm, min_angle, max_angle, max_area, max_aspect;
};

// The meshstep program beside this one (both are built into the same tree and installed
// into the same folder).
std::string sibling_meshstep() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  for (const fs::path& candidate : {self.parent_path() / "meshstep", self.parent_path().parent_path() / "meshstep"})
    if (!ec && fs::exists(candidate)) return candidate.string();
  return "meshstep";
}

// Triangulates (and refines, when asked) an input with --record, as `meshstep` does, and
// returns the log. The run is a separate process: its errors are its own messages.
std::string record_run(const Args& a, const std::string& log) {
  const bool refine = !a.algorithm.empty() || !a.min_angle.empty() || !a.max_angle.empty() || !a.max_area.empty() ||
                      !a.max_aspect.empty();
  std::vector<std::string> args = {sibling_meshstep(), refine ? "refine" : "triangulate", a.input,
                                   "--record", log, "--no-output", "-q"};
  const auto pass = [&](const char* flag, const std::string& value) {
    if (!value.empty()) args.insert(args.end(), {flag, value});
  };
  pass("--algorithm", a.algorithm);
  pass("--min-angle", a.min_angle);
  pass("--max-angle", a.max_angle);
  pass("--max-area", a.max_area);
  pass("--max-aspect", a.max_aspect);
  std::vector<char*> argv;
  for (std::string& s : args) argv.push_back(s.data());
  argv.push_back(nullptr);
  if (!a.quiet) std::fprintf(stderr, "meshstep view: recording %s %s ...\n", args[1].c_str(), a.input.c_str());
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw InputError(a.input, 0, "cannot run " + args[0] + " to triangulate it");
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw InputError(a.input, 0, "its run failed (see above)");
  return log;
}

std::unique_ptr<viewer::Session> open_session(const Args& a, std::string& temporary_log) {
  std::vector<std::string> warnings;
  if (app::is_replay_log(a.input)) return viewer::Session::open_log(a.input);
  const bool is_input = a.input.ends_with(".poly") || a.input.ends_with(".node");
  if (is_input) {
    temporary_log = (fs::temp_directory_path() / ("meshstep-view-" + std::to_string(getpid()) + ".mslog")).string();
    auto session = viewer::Session::open_log(record_run(a, temporary_log));
    return session;
  }
  app::SceneSource source = app::open_scene_source(a.input, &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "%s\n", w.c_str());
  if (source.mesh) return viewer::Session::still(std::move(*source.mesh), a.input);
  return viewer::Session::still(std::move(*source.input), a.input);
}

bool parse_size(const std::string& text, int& w, int& h) {
  char x = 0;
  return std::sscanf(text.c_str(), "%d%c%d", &w, &x, &h) == 3 && (x == 'x' || x == 'X') && w >= 320 && h >= 240 &&
         w <= 8192 && h <= 8192;
}

}  // namespace

int main(int argc, char** argv) {
  const auto started = std::chrono::steady_clock::now();
  CLI::App app(
      "meshstep view: scrub a recorded run forward and backward and see why every point went where it did.\n"
      "INPUT is a replay log (written with --record), a mesh PREFIX, or a .poly/.node input (triangulated,\n"
      "and refined when refinement options are given, recording as it goes).",
      "meshstep view");
  Args a;
  app.add_option("INPUT", a.input, "Replay log, mesh PREFIX, or .poly/.node input")->required();
  app.add_option("--step", a.step, "Open at the mesh after this many steps (default: the end)");
  app.add_option("--event", a.event, "Open after this many events");
  app.add_option("--script", a.script, "Run the actions of this file (see docs/viewer.md), with a fixed frame time");
  app.add_flag("--offscreen", a.offscreen, "No window: draw off screen (EGL or OSMesa), for scripts");
  app.add_option("--gl", a.gl, "Off-screen OpenGL: auto, egl or osmesa")->default_str("auto");
  app.add_option("--size", a.size, "Window size WxH")->default_str("1280x800");
  app.add_option("--algorithm", a.algorithm, "Refine an input with this algorithm (see meshstep list)");
  app.add_option("--min-angle", a.min_angle, "Refine an input: every angle at least DEG");
  app.add_option("--max-angle", a.max_angle, "Refine an input: every angle at most DEG");
  app.add_option("--max-area", a.max_area, "Refine an input: every triangle's area at most A");
  app.add_option("--max-aspect", a.max_aspect, "Refine an input: aspect ratio at most R");
  app.add_flag("-q,--quiet", a.quiet, "Print only errors");
  app.add_option("--frame-log", a.frame_log,
                 "Write each frame's time and allocations to this file (for benchmarks)");
  app.footer(
      "Keys: Space play/pause, Left/Right a step, Shift+Left/Right an event, Page Up/Down a phase,\n"
      "Home/End, +/- speed, F fit, L follow, C colouring, F2-F11 layers, 1-9 bookmarks (Ctrl+1-9 set),\n"
      "? all keys.\n"
      "Examples:\n"
      "  meshstep view assets/examples/lesson.poly --algorithm offcenter --min-angle 30\n"
      "  meshstep view run.mslog --step 45\n"
      "  meshstep view run.mslog --offscreen --script tour.txt");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  viewer::RunOptions options;
  options.started = started;
  if (!parse_size(a.size, options.width, options.height)) {
    std::fprintf(stderr, "meshstep view: --size %s: expected WxH, from 320x240 to 8192x8192\n", a.size.c_str());
    return kExitUsage;
  }
  options.offscreen = a.offscreen;
  options.gl = a.gl;
  options.quiet = a.quiet;
  options.frame_log = a.frame_log;
  // A person's viewer starts where they left it; a script's starts from the defaults, so
  // that it sees the same thing on every machine.
  viewer::Settings settings;
  const std::string settings_file = a.script.empty() ? viewer::settings_path() : "";
  if (!settings_file.empty()) {
    std::vector<std::string> warnings;
    settings = viewer::load_settings(settings_file, warnings);
    for (const std::string& w : warnings) std::fprintf(stderr, "meshstep view: warning: %s\n", w.c_str());
    if (!app.count("--size")) {
      options.width = settings.window_width;
      options.height = settings.window_height;
    }
    options.settings = &settings;
  }
  std::string temporary_log;
  try {
    if (!a.script.empty()) {
      options.script = viewer::read_script(a.script);
      options.script_path = a.script;
    }
    auto session = open_session(a, temporary_log);
    if (a.step >= 0) session->seek_step(static_cast<std::uint64_t>(a.step));
    if (a.event >= 0) session->seek(static_cast<std::uint64_t>(a.event));
    const int status = viewer::run_viewer(std::move(session), options);
    if (!temporary_log.empty()) fs::remove(temporary_log);
    if (!settings_file.empty()) {
      std::error_code ec;
      settings.add_recent(fs::absolute(a.input, ec).string());
      try {
        viewer::save_settings(settings, settings_file);
      } catch (const InputError& e) {
        std::fprintf(stderr, "meshstep view: warning: settings not kept: %s\n", e.what());
      }
    }
    return status;
  } catch (const InputError& e) {
    if (!temporary_log.empty()) fs::remove(temporary_log);
    std::fprintf(stderr, "%s\n", e.what());
    return kExitInput;
  } catch (const render::GlUnavailable& e) {
    if (!temporary_log.empty()) fs::remove(temporary_log);
    std::fprintf(stderr,
                 "meshstep view: cannot open a window or draw: %s\n"
                 "(with no display, run scripts with --offscreen; `meshstep export` writes animations)\n",
                 e.what());
    return kExitInput;
  }
}
