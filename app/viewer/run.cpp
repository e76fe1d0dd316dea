#include "run.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <optional>
#include <utility>
#include <chrono>
#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <filesystem>
#include <thread>
#include <cstdio>
#include <cstdlib>

#include "allocations.hpp"
#include "compare_view.hpp"
#include "compare_with.hpp"
#include "disposal.hpp"
#include "file_dialog.hpp"
#include "host.hpp"
#include "ui_look.hpp"
#include "start_page.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/scene/svg.hpp"
#include "script_player.hpp"
#include "state_json.hpp"
#include "viewer.hpp"
#include "keys.hpp"
#include "live_page.hpp"
#include "workbench_host.hpp"

namespace meshstep::viewer {

namespace {

constexpr double kScriptFrameSeconds = 1.0 / 30.0;

// Ctrl+C in the terminal (or a SIGTERM) closes the viewer as its window's close button does:
// the settings are kept. The signals are taken by a thread of their own (sigwait), not a
// handler: a handler interrupts Xlib's wait for events, which Xlib takes for a lost
// connection and ends the program.
std::atomic<bool> g_interrupted{false};

void watch_for_interrupts(bool window) {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);  // before any other thread starts: they inherit it
  std::thread([set, window] {
    int signal = 0;
    sigwait(&set, &signal);
    g_interrupted = true;
    if (window) glfwPostEmptyEvent();  // wakes the main loop's wait
  }).detach();
}


}  // namespace

int run_viewer(std::unique_ptr<Session> session, const RunOptions& options, Opener& opener) {
  // Runs side by side are opened before any window: a file that is no log is refused first.
  std::optional<SideBySide> side_by_side;
  if (options.side_by_side.size() > 1) {
    side_by_side = open_side_by_side(options.side_by_side);
    session = std::move(side_by_side->leader);
    if (options.start_step >= 0) {
      if (const std::string refused = session->go_to_step(options.start_step, "--step"); !refused.empty())
        throw InputError(session->title(), 0, refused);
    }
    if (options.start_event >= 0) session->seek(static_cast<std::uint64_t>(options.start_event));
  }
  watch_for_interrupts(!options.offscreen);
  IMGUI_CHECKVERSION();
  count_imgui_allocations();
  ImGui::CreateContext();
  struct ContextGuard {
    ~ContextGuard() { ImGui::DestroyContext(); }
  } guard;
  // The look the fonts were last rasterised for: the run's loop makes them again, between
  // frames, when the viewer's scale or theme changes (Ctrl+=, Shift+T, a script).
  UiLook look;
  if (options.settings) look = {options.settings->ui_scale, options.settings->theme};
  if (options.ui_scale > 0.0f) look.scale = options.ui_scale;
  setup_imgui_style(look);

  const std::string title = "meshstep view: " + (session ? session->title() : std::string("start"));
  std::unique_ptr<Host> host = options.offscreen ? make_offscreen_host(options.width, options.height, options.gl)
                                                 : make_window_host(options.width, options.height, title);
  host->set_title(title);
  if (!options.quiet) std::fprintf(stderr, "meshstep view: %s\n", host->describe().c_str());

  // What the window shows: a viewer of a session, or (none yet) the start page. Opening
  // another file (a drop, the start page) makes a new viewer that keeps the options.
  // The workbench (an input edited and re-meshed at once), before the viewer that points
  // to it, so that it outlives every viewer.
  WorkbenchHost bench;
  // Frees the runs the workbench showed before, off this thread; declared before the
  // viewer, it outlives it.
  Disposal disposal;
  std::unique_ptr<Viewer> viewer;
  std::string problem;  // the last file that could not be opened, and why
  bool stopped_run = false;  // `problem` says why the run shown stopped short
  bool tour_started = false;
  // How a session comes to be shown: opened, re-meshed after an edit (not a recent file),
  // or as the leader of runs side by side (its canvas drawn on this thread).
  enum class Shown { opened, edited, side_by_side };
  const auto show = [&](std::unique_ptr<Session> next, Shown how = Shown::opened) {
    const bool side = how == Shown::side_by_side, edited = how == Shown::edited;
    Settings carried = options.settings ? *options.settings : Settings{};
    if (options.ui_scale > 0.0f) carried.ui_scale = options.ui_scale;
    if (viewer) viewer->capture(carried);
    const std::string path = next->title();
    // Side by side, every run's canvas has a worker of its own (compare_view.hpp), none
    // the viewer's.
    // The workbench's run before: its session and canvas worker freed on a thread of their
    // own (a big run's took 370 ms on this one, in the frame that shows the next run).
    Viewer::Leftovers old;
    if (viewer && edited) old = viewer->release_run();
    viewer = std::make_unique<Viewer>(std::move(next), CanvasOptions{side ? CanvasMode::this_thread : options.canvas,
                                                                     host->gl_library()});
    if (old.session || old.worker) disposal.dispose(std::move(old));
    // The title names what the window shows now: a live run's log, a file opened later.
    host->set_title("meshstep view: " + path);
    viewer->window_title = host->title();
    viewer->workbench = &bench;
    if (options.settings || carried != Settings{}) viewer->apply(carried);
    // A tour's log is a temporary one, and its title the tour's: no recent file to keep.
    const bool tour_log = options.tour && !tour_started;
    if (tour_log) {
      tour_started = true;
      viewer->set_tour(options.tour);
      options.tour->go(*viewer, 0);
    }
    if (options.settings && !edited && !tour_log) {
      std::error_code ec;
      options.settings->add_recent(std::filesystem::absolute(path, ec).string());
    }
    problem.clear();
    stopped_run = false;
  };
  // An input (.poly, .node) runs live: the window shows the mesh as the run makes it, and
  // opens the whole log when it ends.
  std::unique_ptr<LiveView> live;
  std::string compare_base;  // "Compare with...": the log the live run will be shown beside
  int status = 0;
  const auto open = [&](const std::string& path, const RefineOptions& refine) {
    bench = WorkbenchHost{};  // another file: the edits end (saved or not)
    try {
      if (is_input(path)) {
        bench.know_recipe(path, refine.operation ? std::vector<Operation>{*refine.operation} : std::vector<Operation>{});
        live.reset();  // a run still going is stopped
        live = std::make_unique<LiveView>(opener.start_live(path, refine, host->gl_library()));
        host->set_title("meshstep view: " + path + " (running)");
        problem.clear();
      } else {
        show(opener.open(path));
      }
    } catch (const InputError& e) {
      problem = e.what();
    }
  };
  // When the live run has ended: its log opens, or the window says why it failed.
  // `wait_for_log`: a script's action comes next, which looks at the run once it is open.
  const auto end_live = [&](bool wait_for_log) {
    if (!live || live->run->running()) return;
    LiveRun& run = *live->run;
    if (run.succeeded() && !compare_base.empty()) {
      try {
        SideBySide both = open_side_by_side({compare_base, run.log()});
        // The new run by its input's name, not its temporary log's.
        (both.leader_index == 1 ? both.leader : both.runs[1])->set_title(run.input() + " (compared)");
        show(std::move(both.leader), Shown::side_by_side);
        viewer->show_side_by_side(std::move(both));
      } catch (const InputError& e) {
        problem = e.what();
      }
      compare_base.clear();
    } else if (run.succeeded()) {
      // Opened off the window's thread: the live page stays until the log is open.
      if (!live->opening) live->opening = std::make_unique<LogOpening>(run.log(), run.input());
      if (!live->opening->ready() && !wait_for_log) return;
      if (std::unique_ptr<Session> s = live->opening->take()) {
        if (options.start_step >= 0) s->seek_step(static_cast<std::uint64_t>(options.start_step));
        if (options.start_event >= 0) s->seek(static_cast<std::uint64_t>(options.start_event));
        show(std::move(s));
      } else {
        problem = live->opening->error();
      }
    } else if (!run.cancelled()) {
      const std::string said = run.messages();
      // A run that stopped (at its memory budget) has finished its log: it opens, as far as
      // the run went, with the run's words beside it. One that failed has none.
      std::error_code ec;
      if (std::filesystem::exists(run.log(), ec)) {
        try {
          std::unique_ptr<Session> s = Session::open_log(run.log());
          s->set_title(run.input());
          show(std::move(s));
          stopped_run = true;
        } catch (const InputError&) {
        }
      }
      problem = said.empty() ? run.input() + ": its run failed" : said;
      if (!options.quiet || !host->interactive() || stopped_run) std::fprintf(stderr, "%s\n", problem.c_str());
      if (!host->interactive() && !stopped_run) status = 1;  // a script's input that cannot run: an error
    }
    live.reset();
  };
  if (session && side_by_side) {
    show(std::move(session), Shown::side_by_side);
    viewer->show_side_by_side(std::move(*side_by_side));
  } else if (session) {
    show(std::move(session));
  }
  if (!options.live_input.empty()) open(options.live_input, options.live_refine);

  ScriptPlayer script(options.script, options.script_path);
  script.set_workbench(&bench);
  // After an edit (the canvas's last frame, a key, a script's action): the input's new mesh,
  // in the view the last one had when the input is still all in it (workbench.hpp).
  const auto show_edited = [&] {
    // A script takes the workbench's live run when it looks (or watches it end).
    std::unique_ptr<Session> edited =
        bench.take_session(options.script.empty() || script.waits_for_live() || script.watching() || script.done());
    if (!edited) return;
    const bool keep = viewer && bench.showing && bench.in_view(viewer->camera());
    const scene::Camera camera = viewer ? viewer->camera() : scene::Camera{};
    // The viewer that showed the last run shows this one (swap_session.cpp): a new viewer
    // per edit cost more than the re-meshing.
    if (viewer && bench.showing && viewer->swap_session(edited)) {
      const std::string path = viewer->session().title();
      host->set_title("meshstep view: " + path);
      viewer->window_title = host->title();
      problem.clear();
      stopped_run = false;
    } else {
      show(std::move(edited), Shown::edited);
    }
    if (keep) viewer->keep_camera(camera);
    bench.showing = true;
  };
  const bool scripted = !options.script.empty();

  struct FrameRecord {
    double end_ms, frame_ms;
    std::uint64_t allocations, position, shown;
    bool live;  // a live run went during the frame (the page's, or the workbench's re-meshing)
  };
  std::vector<FrameRecord> frames;
  frames.reserve(1 << 16);  // recording a frame must not allocate (it is one of the measured)
  scene::Image capture;
  using Clock = std::chrono::steady_clock;
  Clock::time_point last = Clock::now();
  std::string picked;
  RefineOptions picked_refine;
  while (!(viewer && viewer->quit_requested) && !g_interrupted && status == 0) {
    // Scripts run on a fixed frame time, so that what they see does not depend on the
    // machine's speed; people get the wall clock.
    const Clock::time_point now = Clock::now();
    const double wall = std::chrono::duration<double>(now - last).count();
    const double seconds = scripted || !host->interactive() ? kScriptFrameSeconds : std::max(1e-4, wall);
    last = now;
    const std::uint64_t allocations_before = allocations();
    if (!host->begin_frame(seconds)) break;
    // Between frames: a file dropped on the window, or picked on the start page.
    if (const std::string dropped = host->take_dropped(); !dropped.empty()) open(dropped, {});
    // A script's actions look at the run once it has ended (all but `frames`, `peek` and
    // `quit`), so that what they see does not depend on the machine's speed.
    if (live && scripted && script.waits_for_live())
      while (live->run->running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (scripted && script.waits_for_live()) bench.wait_live();  // the workbench's, likewise
    end_live(scripted && script.waits_for_live());
    if (status != 0) break;
    show_edited();  // an edit of the last frame's, before a script looks
    if (scripted) script.set_live_state(live ? live_state_json(*live) : std::string());
    const bool wants_capture = scripted && !script.done() && script.before_frame(viewer.get(), picked, problem);
    if (script.quit()) break;
    // "Compare with...": the input run again, live; end_live shows both when it ends.
    if (viewer && !viewer->compare_words.empty()) {
      const std::string words = std::exchange(viewer->compare_words, std::string());
      try {
        const CompareWith c = compare_with(*viewer->session().log(), words);
        live.reset();
        live = std::make_unique<LiveView>(opener.start_live(c.input, c.refine, host->gl_library()));
        host->set_title("meshstep view: " + c.input + " (running, to compare)");
        compare_base = c.base_log;
        problem.clear();
      } catch (const std::exception& e) {  // RunSpecError, InputError: said, nothing runs
        viewer->notify(std::string("compare with: ") + e.what());
        if (!host->interactive()) std::fprintf(stderr, "meshstep view: compare with: %s\n", e.what());
      }
    }
    if (!picked.empty()) {
      open(picked, picked_refine);
      picked.clear();
      picked_refine = {};
    }
    show_edited();  // an edit of the script's
    // Presentation: a new UI scale or theme rasterises the fonts again and uploads them
    // before the frame that uses them; full screen is the window's.
    if (viewer) {
      const UiLook wanted{viewer->ui_scale, viewer->session().options().theme};
      if (wanted != look) {
        look = wanted;
        apply_ui_look(look);
        host->reload_fonts();
      }
      if (viewer->full_screen != host->full_screen() && !host->set_full_screen(viewer->full_screen)) {
        viewer->full_screen = host->full_screen();
        viewer->notify(host->interactive() ? "full screen: the window system has no monitor to fill"
                                           : "full screen: off screen there is no window to fill the screen with");
      }
    }
    ImGui::NewFrame();
    if (live) draw_live_page(*live, host->width(), host->height());
    else if (viewer) viewer->frame(host->width(), host->height(), seconds);
    else {
      draw_start_page(host->width(), host->height(), options.settings, picked, picked_refine);
      // Ctrl+N (and the page's New input button): an empty input, edited in a viewer.
      if (start_page_wants_new() || (ImGui::GetIO().KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_N, false)))
        bench.start_new();
    }
    // The file dialog (Ctrl+O, the Open... buttons): its pick opens as the start page's does.
    draw_file_dialog(viewer ? std::string_view(viewer->session().title()) : std::string_view(), picked);
    if (!problem.empty()) draw_problem(problem, stopped_run ? "the run stopped short" : "cannot open", viewer != nullptr);
    ImGui::Render();
    const bool capture_window = viewer && !viewer->window_capture_path.empty();
    host->end_frame(wants_capture || capture_window ? &capture : nullptr);
    if (wants_capture) script.after_frame(capture);
    if (capture_window) {
      try {
        scene::write_png(viewer->window_capture_path, capture, 6);
      } catch (const std::exception& e) {
        viewer->export_status = std::string("failed: ") + e.what();
      }
      viewer->window_capture_path.clear();
    }
    const std::uint64_t position = viewer ? viewer->session().cursor_info().position : 0;
    const std::uint64_t shown = viewer ? viewer->session().shown_position() : 0;
    if (!options.frame_log.empty() && frames.size() < frames.capacity()) {
      const Clock::time_point end = Clock::now();
      frames.push_back({std::chrono::duration<double, std::milli>(end - options.started).count(),
                        std::chrono::duration<double, std::milli>(end - now).count(),
                        allocations() - allocations_before, position, shown, live || bench.live_running()});
    }
    if (!host->interactive() && (!scripted || script.done())) break;
    // An idle window sleeps until an event; one with something to show soon does not.
    // Runs side by side: their pictures still coming are something to show soon too.
    const bool busy = live || bench.remeshing_live() ||
                      (viewer && (viewer->session().playback().playing || viewer->canvas_drawing() ||
                                  (viewer->compare() && viewer->compare()->drawing())));
    if (host->interactive() && !scripted && !busy && picked.empty()) glfwWaitEventsTimeout(0.1);
    else if (host->interactive() && !scripted && busy && !(viewer && viewer->session().playback().playing))
      glfwWaitEventsTimeout(1.0 / 60.0);
  }
  if (options.settings) {
    if (viewer) viewer->capture(*options.settings);
    // The window's own size, not the screen's it may fill.
    options.settings->window_width = host->windowed_width();
    options.settings->window_height = host->windowed_height();
  }
  if (!options.frame_log.empty()) {
    std::string text = "# frame end_ms frame_ms allocations position shown live\n";
    char line[128];
    for (std::size_t i = 0; i < frames.size(); ++i) {
      std::snprintf(line, sizeof line, "%zu %.3f %.3f %llu %llu %lld %d\n", i, frames[i].end_ms, frames[i].frame_ms,
                    static_cast<unsigned long long>(frames[i].allocations),
                    static_cast<unsigned long long>(frames[i].position),
                    frames[i].shown == UINT64_MAX ? -1LL : static_cast<long long>(frames[i].shown),
                    frames[i].live ? 1 : 0);
      text += line;
    }
    io::write_file_atomically(options.frame_log, text);
  }
  return status;
}

}  // namespace meshstep::viewer
