// meshstep-view: the viewer (`meshstep view` runs it). See README.md, "The viewer".

#include <CLI/CLI.hpp>
#include <malloc.h>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/file_roles.hpp"
#include "common/tour_run.hpp"
#include "meshstep/error.hpp"
#include "render/gl_context.hpp"
#include "render/leak_check.hpp"
#include "compare_view.hpp"
#include "open_input.hpp"
#include "run.hpp"
#include "settings.hpp"
#include "sibling_program.hpp"
#include "tour_guide.hpp"
#include "ui_look.hpp"

namespace {

using namespace meshstep;
namespace fs = std::filesystem;

constexpr int kExitUsage = 2, kExitInput = 1;

struct Args {
  std::string input;
  std::vector<std::string> inputs;  // as given; two to four logs: side by side
  std::int64_t step = -1, event = -1;
  std::string script, window = "1280x800", gl = "auto";
  bool offscreen = false, quiet = false;
  std::string frame_log, canvas = "auto";
  std::string ui_scale;  // "" when not given
  std::string tour;      // a guided tour (docs/tours.md): its run is recorded, then played
  // Of an input, as `meshstep refine` takes them (the window's size is --window, so that
  // --size means what it means to refine).
  std::string algorithm, min_angle, max_angle, max_area, max_aspect, size, max_memory;
};

// The refinement the command line asks of an input (none: triangulate it), read by the run
// description's parser. Throws RunSpecError.
viewer::RefineOptions live_refinement(const Args& a) {
  viewer::RefineOptions refine;
  refine.max_memory = a.max_memory;
  const std::pair<const char*, const std::string*> given[] = {{"algorithm", &a.algorithm},
                                                              {"min-angle", &a.min_angle},
                                                              {"max-angle", &a.max_angle},
                                                              {"max-area", &a.max_area},
                                                              {"max-aspect", &a.max_aspect},
                                                              {"size", &a.size}};
  for (const auto& [name, text] : given) {
    if (text->empty()) continue;
    if (!refine.operation) refine.operation.emplace();
    set_option(*refine.operation, name, *text);
  }
  return refine;
}

bool parse_size(const std::string& text, int& w, int& h) {
  char x = 0;
  return std::sscanf(text.c_str(), "%d%c%d", &w, &x, &h) == 3 && (x == 'x' || x == 'X') && w >= 320 && h >= 240 &&
         w <= 8192 && h <= 8192;
}

}  // namespace

int main(int argc, char** argv) {
  const auto started = std::chrono::steady_clock::now();
  meshstep::render::check_leaks_before_gl_in_this_program();
  CLI::App app(
      "meshstep view: scrub a recorded run forward and backward and see why every point went where it did.\n"
      "INPUT is a replay log (written with --record), a mesh PREFIX, or a .poly/.node input (triangulated,\n"
      "and refined when refinement options are given, recording as it goes).",
      "meshstep view");
  Args a;
  app.add_option("INPUT", a.inputs,
                 "Replay log, mesh PREFIX, or .poly/.node input (none: the start page); two to four logs are\n"
                 "shown side by side, one timeline driving them all");
  app.add_option("--step", a.step, "Open at the mesh after this many steps (default: the end)");
  app.add_option("--event", a.event, "Open after this many events");
  app.add_option("--tour", a.tour,
                 "Play a guided tour (docs/tours.md): its run is recorded first, then N and P go from stop to\n"
                 "stop, each with its caption on the canvas (no INPUT: the tour names its own)");
  app.add_option("--script", a.script, "Run the actions of this file (see docs/viewer.md), with a fixed frame time");
  app.add_flag("--offscreen", a.offscreen, "No window: draw off screen (EGL or OSMesa), for scripts");
  app.add_option("--gl", a.gl, "Off-screen OpenGL: auto, egl or osmesa")->default_str("auto");
  app.add_option("--window", a.window, "Window size WxH")->default_str("1280x800");
  app.add_option("--algorithm", a.algorithm, "Refine an input with this algorithm (see meshstep list)");
  app.add_option("--min-angle", a.min_angle, "Refine an input: every angle at least DEG");
  app.add_option("--max-angle", a.max_angle, "Refine an input: every angle at most DEG");
  app.add_option("--max-area", a.max_area, "Refine an input: every triangle's area at most A");
  app.add_option("--max-aspect", a.max_aspect, "Refine an input: aspect ratio at most R");
  app.add_option("--size", a.size, "Refine an input: every edge at most L long, or a size grid (.asc), as refine --size");
  app.add_option("--max-memory", a.max_memory,
                 "Refine an input: stop at this memory budget (8G, 500M; default a quarter of the\n"
                 "machine's, as meshstep refine), and show the run as far as it went");
  app.add_option("--ui-scale", a.ui_scale,
                 "Scale every font and panel by S (0.75 to 3, in steps of 0.25; Ctrl+= and Ctrl+- in the\n"
                 "viewer), for a projector or a high-resolution screen; kept in the settings");
  app.add_flag("-q,--quiet", a.quiet, "Print only errors");
  app.add_option("--canvas", a.canvas,
                 "Who draws the canvas: auto (a thread of its own for runs of more than 20,000 vertices, so\n"
                 "that scrubbing never waits for a picture), main or worker")
      ->check(CLI::IsMember({"auto", "main", "worker"}))
      ->default_str("auto");
  app.add_option("--frame-log", a.frame_log,
                 "Write each frame's time and allocations to this file (for benchmarks)");
  app.footer(
      "Keys: Space play/pause, Left/Right a step, Shift+Left/Right an event, Page Up/Down a phase,\n"
      "Home/End, +/- speed, F fit, L follow, C colouring, F2-F10 and F12 layers, 1-9 bookmarks (Ctrl+1-9\n"
      "set), presenting: Ctrl+=/Ctrl+- UI scale, F11 full screen, Tab hide the panels, Shift+T high contrast,\n"
      "V 2D/3D (a terrain's run: Ctrl+arrows turn it, Z/Shift+Z stretch the heights, drag to turn),\n"
      "? all keys.\n"
      "Examples:\n"
      "  meshstep view assets/examples/lesson.poly --algorithm offcenter --min-angle 30\n"
      "  meshstep view run.mslog --step 45\n"
      "  meshstep terrain volcano.asc --max-error 1% --record v.mslog && meshstep view v.mslog\n"
      "  meshstep view run.mslog --offscreen --script tour.txt");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  if (a.inputs.size() > viewer::kMaxRunsSideBySide) {
    std::fprintf(stderr, "meshstep view: %zu files given: at most %zu runs side by side\n", a.inputs.size(),
                 viewer::kMaxRunsSideBySide);
    return kExitUsage;
  }
  if (!a.inputs.empty()) a.input = a.inputs[0];
  viewer::RunOptions options;
  options.started = started;
  if (!parse_size(a.window, options.width, options.height)) {
    std::fprintf(stderr, "meshstep view: --window %s: expected WxH, from 320x240 to 8192x8192\n", a.window.c_str());
    return kExitUsage;
  }
  // --frame-log is the one file the command line names for writing (issue 31).
  app::FileRoles roles;
  for (std::size_t i = 1; i < a.inputs.size(); ++i) roles.reads(a.inputs[i]);
  if (const auto clash = roles
                             .reads_pslg(a.input)
                             .reads_mesh(a.input)
                             .reads(a.script)
                             .reads(a.tour)
                             .writes("--frame-log", a.frame_log, "frame log")
                             .clash()) {
    std::fprintf(stderr, "meshstep view: %s\n", clash->c_str());
    return kExitUsage;
  }
  std::optional<float> ui_scale;
  if (!a.ui_scale.empty() && !(ui_scale = viewer::parse_ui_scale(a.ui_scale))) {
    std::fprintf(stderr, "meshstep view: --ui-scale %s: expected 0.75 to 3, in steps of 0.25 (1.25, 1.5, 2...)\n",
                 a.ui_scale.c_str());
    return kExitUsage;
  }
  if (ui_scale) options.ui_scale = *ui_scale;
  options.offscreen = a.offscreen;
  options.gl = a.gl;
  options.quiet = a.quiet;
  options.frame_log = a.frame_log;
  options.canvas = a.canvas == "main"     ? viewer::CanvasMode::this_thread
                   : a.canvas == "worker" ? viewer::CanvasMode::worker
                                          : viewer::CanvasMode::automatic;
  // A person's viewer starts where they left it; a script's starts from the defaults, so
  // that it sees the same thing on every machine.
  viewer::Settings settings;
  const std::string settings_file = a.script.empty() ? viewer::settings_path() : "";
  if (!settings_file.empty()) {
    std::vector<std::string> warnings;
    settings = viewer::load_settings(settings_file, warnings);
    for (const std::string& w : warnings) std::fprintf(stderr, "meshstep view: warning: %s\n", w.c_str());
    if (!app.count("--window")) {
      options.width = settings.window_width;
      options.height = settings.window_height;
    }
    if (ui_scale) settings.ui_scale = *ui_scale;  // asked for: kept for the next time too
    options.settings = &settings;
  }
  viewer::Opener opener;
  try {
    if (!a.script.empty()) {
      options.script = viewer::read_script(a.script);
      options.script_path = a.script;
    }
    std::unique_ptr<viewer::Session> session;
    // A tour names its input and its run: recorded here, into a folder that lives as long as
    // the viewer (its background jobs read the log again by its path).
    std::optional<app::ScratchFolder> tour_scratch;
    if (!a.tour.empty()) {
      if (!a.input.empty()) {
        std::fprintf(stderr, "meshstep view: --tour %s names its own input: give no INPUT (%s) with it\n", a.tour.c_str(),
                     a.input.c_str());
        return kExitUsage;
      }
      teach::Tour tour = teach::read_tour(a.tour);
      tour_scratch.emplace();
      if (!a.quiet) std::fprintf(stderr, "meshstep view: recording the tour's run of %s...\n", tour.input.c_str());
      const std::string log = app::record_tour_run(tour, viewer::sibling_program("meshstep"), *tour_scratch);
      session = viewer::Session::open_log(log);
      session->set_title(tour.title.empty() ? a.tour : tour.title);
      options.tour = std::make_shared<viewer::TourGuide>(std::move(tour), *session->log());
    }
    // A mistyped path is the commonest bad input: say so, not just that it cannot be read.
    if (std::error_code ec; !a.input.empty() && !fs::exists(a.input, ec))
      throw InputError(a.input, 0, "does not exist (no such file: check the path)");
    if (a.inputs.size() > 1) {
      // Side by side: recorded runs only (an input would have to run first).
      for (const std::string& path : a.inputs) {
        if (std::error_code ec; !fs::exists(path, ec)) throw InputError(path, 0, "does not exist (no such file: check the path)");
        if (viewer::is_input(path)) {
          std::fprintf(stderr,
                       "meshstep view: %s: runs side by side are replay logs (record one: meshstep refine %s ... "
                       "--record RUN.mslog)\n",
                       path.c_str(), path.c_str());
          return kExitUsage;
        }
      }
      options.side_by_side = a.inputs;
      // Each run's worker replays on a thread of its own, and glibc gives each such thread
      // an arena whose freed memory stays in the process: four 1e5-point runs held about
      // 130 MiB more with the default (8 x cores arenas) than with two (docs/viewer.md).
      mallopt(M_ARENA_MAX, 2);
      options.start_step = a.step;
      options.start_event = a.event;
    } else if (viewer::is_input(a.input)) {
      if (std::FILE* f = std::fopen(a.input.c_str(), "rb")) std::fclose(f);
      else throw InputError(a.input, 0, "cannot be read");
      options.live_input = a.input;  // run live: the window shows it as it goes
      try {
        options.live_refine = live_refinement(a);
      } catch (const RunSpecError& e) {
        std::fprintf(stderr, "meshstep view: %s\n", e.what());
        return kExitUsage;
      }
      options.start_step = a.step;
      options.start_event = a.event;
    } else if (!a.input.empty()) {
      session = opener.open(a.input);
      if (a.step != -1 && session->log()) {  // -1: the end (the default)
        if (const std::string refused = session->go_to_step(a.step, "--step"); !refused.empty()) {
          std::fprintf(stderr, "meshstep view: %s\n", refused.c_str());
          return kExitUsage;
        }
      }
      if (a.event >= 0) session->seek(static_cast<std::uint64_t>(a.event));
    }
    const int status = viewer::run_viewer(std::move(session), options, opener);
    if (!settings_file.empty()) {
      try {
        viewer::save_settings(settings, settings_file);
      } catch (const InputError& e) {
        std::fprintf(stderr, "meshstep view: warning: settings not kept: %s\n", e.what());
      }
    }
    return status;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitInput;
  } catch (const render::GlUnavailable& e) {
    std::fprintf(stderr,
                 "meshstep view: cannot open a window or draw: %s\n"
                 "(with no display, run scripts with --offscreen; `meshstep export` writes animations)\n",
                 e.what());
    return kExitInput;
  }
}
