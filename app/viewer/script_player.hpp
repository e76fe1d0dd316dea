// Plays a script (script.hpp) into the viewer, frame by frame: actions that change state
// take no frame; a key, a click, a drag, `frames` and `play` take the frames they need.
#pragma once

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "edit_script.hpp"
#include "compare_view.hpp"
#include "keys.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/scene/image.hpp"
#include "meshstep/scene/svg.hpp"
#include "script.hpp"
#include "state_json.hpp"
#include "teach_script.hpp"
#include "ui_look.hpp"
#include "viewer.hpp"
#include "workbench_host.hpp"

namespace meshstep::viewer {

class ScriptPlayer {
 public:
  ScriptPlayer(const std::vector<ScriptAction>& actions, const std::string& path) : actions_(actions), path_(path) {}

  // Whether the next action must wait for a live run to end: all but `frames`, `peek` and
  // `quit` look at the run, and a script sees the same whatever the machine's speed.
  bool waits_for_live() const {
    if (frames_left_ > 0 || !pending_.empty() || next_ >= actions_.size()) return false;
    const std::string& v = actions_[next_].verb;
    return !(v == "frames" || v == "peek" || v == "quit" || v == "screenshot" || v == "watch");
  }
  // (A screenshot does not wait: it shows the live page, for teaching material; what it
  // shows depends on the machine's speed.)
  // What `peek` writes while a live run goes (live_page.hpp); cleared when it ends.
  void set_live_state(std::string json) { live_state_ = std::move(json); }

  // Where the workbench's actions (edit_script.hpp) go.
  void set_workbench(WorkbenchHost* host) { workbench_ = host; }

  // Whether `watch` draws frames now.
  bool watching() const { return watching_; }
  bool done() const {
    return next_ >= actions_.size() && frames_left_ == 0 && pending_.empty() && !pause_now_ && !waiting_;
  }
  bool quit() const { return quit_; }

  // Before ImGui::NewFrame: sets this frame's input. Returns true when the frame must be
  // captured for a screenshot.
  // `viewer` is null on the start page; `open` receives the file of an `open` action (the
  // loop opens it before the next frame).
  bool before_frame(Viewer* viewer, std::string& open, const std::string& problem) {
    ImGuiIO& io = ImGui::GetIO();
    // `wait-until`, `wait-input`: the window's own input, untouched, until the file is there
    // or the time is up.
    if (waiting_) {
      const bool file_there = wait_for_ && std::filesystem::exists(wait_for_->args[0]);
      if (!file_there && std::chrono::steady_clock::now() < wait_end_) return false;
      if (!file_there && wait_for_)
        throw InputError(path_, static_cast<std::size_t>(wait_for_->line),
                         "wait-until: " + wait_for_->args[0] + " did not appear within " + wait_for_->args[1] + " s");
      waiting_ = false;
      wait_for_ = nullptr;
    }
    release(io);
    // `watch`: frames, touching nothing, for as long as a live run goes.
    if (watching_ && (!live_state_.empty() || (workbench_ && workbench_->remeshing_live()))) return false;
    watching_ = false;
    // `play N` pauses after its N-th frame has played, not before.
    if (pause_now_ && viewer) {
      viewer->session().playback().playing = false;
      pause_now_ = false;
    }
    while (frames_left_ == 0 && pending_.empty() && next_ < actions_.size() && !quit_ && open.empty()) {
      if (!live_state_.empty() && waits_for_live()) break;  // the loop waits for the run first
      const ScriptAction& a = actions_[next_++];
      if (a.verb == "open") {
        open = a.args[0];
        pending_.push_back({});  // the frame that shows it
        break;
      }
      if (a.verb == "peek" && !live_state_.empty()) {
        io::write_file_atomically(a.args[0], live_state_);
        continue;
      }
      if ((a.verb == "state" || a.verb == "peek") && !viewer) {
        io::write_file_atomically(a.args[0], "{\n  \"page\": \"start\",\n  \"problem\": \"" + escaped(problem) + "\"\n}\n");
        continue;
      }
      if (!viewer && needs_viewer(a.verb))
        throw InputError(path_, static_cast<std::size_t>(a.line), "no run is open yet for '" + a.verb + "' (open one first)");
      if (run(a, viewer, io)) break;
    }
    if (!pending_.empty()) {
      const Input in = pending_.front();
      pending_.erase(pending_.begin());
      apply(in, io);
    } else if (frames_left_ > 0) {
      --frames_left_;
      if (frames_left_ == 0 && stop_playing_) {
        pause_now_ = true;
        stop_playing_ = false;
      }
    }
    return capture_ != nullptr && frames_left_ == 0;  // the screenshot's last frame
  }

  void after_frame(const scene::Image& captured) {
    if (!capture_) return;
    scene::write_png(capture_->args[0], captured, 6);
    capture_ = nullptr;
  }

 private:
  static bool ends_with(const std::string& s, const char* tail) {
    const std::string t(tail);
    return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
  }

  static bool needs_viewer(const std::string& verb) {
    return !(verb == "frames" || verb == "key" || verb == "type" || verb == "mouse" || verb == "click" || verb == "drag" ||
             verb == "drag-path" || verb == "wait-until" || verb == "wait-input" || verb == "wheel" ||
             verb == "screenshot" || verb == "quit" || verb == "watch" || is_edit_action(verb));
  }

  static std::string no_heights(Viewer& viewer) {
    return viewer.session().title() +
           " has no heights: only a terrain's run (meshstep terrain GRID --record LOG) is seen in 3D";
  }

  static std::string escaped(const std::string& s) {
    std::string out;
    for (const char c : s) {
      if (c == '"' || c == '\\') out += '\\';
      if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
    return out;
  }

  struct Input {
    int key = -1;
    bool shift = false, ctrl = false;
    bool button = false;  // left button held this frame
    float dx = 0, dy = 0, wheel = 0;
    const std::string* text = nullptr;  // typed this frame (the action's text)
  };

  void release(ImGuiIO& io) {
    if (held_key_ >= 0) io.KeysDown[held_key_] = false;
    held_key_ = -1;
    io.KeyShift = io.KeyCtrl = false;
    io.MouseWheel = 0.0f;
    io.MouseDown[0] = false;
  }

  void apply(const Input& in, ImGuiIO& io) {
    if (in.key >= 0) {
      io.KeysDown[in.key] = true;
      held_key_ = in.key;
      io.KeyShift = in.shift;
      io.KeyCtrl = in.ctrl;
    }
    mouse_x_ += in.dx;
    mouse_y_ += in.dy;
    io.MousePos = ImVec2(mouse_x_, mouse_y_);
    io.MouseDown[0] = in.button;
    io.MouseWheel = in.wheel;
    if (in.text) io.AddInputCharactersUTF8(in.text->c_str());
  }

  static void wait_for_background(Viewer& viewer) {
    if (!viewer.session().log()) return;
    while (!viewer.history().ready() || !viewer.plots().ready() || (viewer.compare() && !viewer.compare()->plots_ready()))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    viewer.settle_timeline_marks();
  }

  // Runs one action; true when it takes frames (the loop then draws them).
  // `viewer` is null only for the actions that need none (needs_viewer).
  bool run(const ScriptAction& a, Viewer* viewer, ImGuiIO& io) {
    const auto& v = a.verb;
    // What a script looks at is the cursor's moment, even when a worker draws the canvas.
    // A screenshot also waits for the background work (the history's index, the plots), so
    // that the window it takes does not depend on the machine's speed.
    if (viewer && (v == "screenshot" || v == "canvas" || v == "state" || v == "select" || v == "wait" ||
                   v == "settle"))
      viewer->settle_canvas();
    if (viewer && (v == "screenshot" || v == "wait")) wait_for_background(*viewer);
    // The state counts the timeline's marks: the pass over the events, if one runs, first.
    if (viewer && v == "state") viewer->settle_timeline_marks();
    if (v == "seek") {
      if (a.args[0] == "start") viewer->session().to_start();
      else if (a.args[0] == "end") viewer->session().to_end();
      else if (a.args[0] == "step") {
        // As the go-to box: a step outside the run is refused, in the words of every command.
        const std::string refused = viewer->session().go_to_step(std::strtoll(a.args[1].c_str(), nullptr, 10));
        if (!refused.empty()) throw InputError(path_, static_cast<std::size_t>(a.line), "seek step: " + refused);
      }
      else viewer->session().seek(std::strtoull(a.args[1].c_str(), nullptr, 10));
      return false;
    }
    if (v == "tour" || v == "quiz") {
      run_teaching_action(a, *viewer, path_);
      return false;
    }
    if (v == "watch") {
      watching_ = !live_state_.empty() || (workbench_ && workbench_->remeshing_live());
      return watching_;
    }
    if (v == "frames") {
      frames_left_ = std::strtoull(a.args[0].c_str(), nullptr, 10);
      return frames_left_ > 0;
    }
    if (v == "play") {
      frames_left_ = std::strtoull(a.args[0].c_str(), nullptr, 10);
      if (!viewer->session().playback().playing) viewer->session().toggle_play();
      stop_playing_ = true;
      return frames_left_ > 0;
    }
    if (v == "key") {
      const Chord c = *parse_chord(a.args[0]);
      pending_.push_back({c.key, c.shift, c.ctrl});
      pending_.push_back({});  // released on the next frame
      return true;
    }
    if (v == "type") {
      Input typing;
      typing.text = &a.args[0];
      pending_.push_back(typing);
      return true;
    }
    if (v == "toggle-marks") {
      viewer->timeline_marks.toggle(*parse_mark(a.args[0]));
      return false;
    }
    if (v == "toggle") {
      viewer->toggle_layer(*scene::parse_layer(a.args[0]));
      return false;
    }
    if (v == "color-by") {
      viewer->session().set_color_by(*scene::parse_color_by(a.args[0]));
      return false;
    }
    if (v == "speed") {
      viewer->session().playback().speed = std::clamp(std::strtod(a.args[0].c_str(), nullptr), Playback::kMinSpeed, Playback::kMaxSpeed);
      return false;
    }
    if (v == "unit") {
      viewer->session().playback().unit = a.args[0] == "event" ? Unit::event : a.args[0] == "step" ? Unit::step : Unit::phase;
      return false;
    }
    if (v == "mouse") {
      mouse_x_ = std::strtof(a.args[0].c_str(), nullptr);
      mouse_y_ = std::strtof(a.args[1].c_str(), nullptr);
      pending_.push_back({});
      return true;
    }
    if (v == "click") {
      Input down;
      down.button = true;
      pending_.push_back(down);
      pending_.push_back({});
      return true;
    }
    if (v == "drag") {
      const float dx = std::strtof(a.args[0].c_str(), nullptr), dy = std::strtof(a.args[1].c_str(), nullptr);
      Input press;
      press.button = true;
      pending_.push_back(press);
      for (int i = 0; i < 4; ++i) {
        Input move = press;
        move.dx = dx / 4.0f;
        move.dy = dy / 4.0f;
        pending_.push_back(move);
      }
      pending_.push_back({});
      return true;
    }
    if (v == "drag-path") {
      Input press;
      press.button = true;
      pending_.push_back(press);
      for (std::size_t i = 0; i + 1 < a.args.size(); i += 2) {
        Input move = press;
        move.dx = std::strtof(a.args[i].c_str(), nullptr);
        move.dy = std::strtof(a.args[i + 1].c_str(), nullptr);
        pending_.push_back(move);
      }
      pending_.push_back({});
      return true;
    }
    if (v == "wait-until" || v == "wait-input") {
      waiting_ = true;
      wait_for_ = v == "wait-until" ? &a : nullptr;
      const double seconds = std::strtod(a.args[v == "wait-until" ? 1 : 0].c_str(), nullptr);
      wait_end_ = std::chrono::steady_clock::now() +
                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
      return true;
    }
    if (v == "wheel") {
      Input turn;
      turn.wheel = std::strtof(a.args[0].c_str(), nullptr);
      pending_.push_back(turn);
      return true;
    }
    if (v == "screenshot") {
      // Two frames: ImGui lays out what changed (a panel grown by the background work) on
      // the first, and the second is the one taken.
      capture_ = &a;
      frames_left_ = 2;
      return true;
    }
    if (v == "canvas") {
      const std::string& file = a.args[0];
      if (ends_with(file, ".svg")) io::write_file_atomically(file, scene::to_svg(viewer->shown_scene(), viewer->camera()));
      else scene::write_png(file, viewer->canvas_picture(), 6);
      return false;
    }
    if (v == "state" || v == "peek") {
      io::write_file_atomically(a.args[0], state_json(*viewer));
      return false;
    }
    if (v == "view") {
      if (!viewer->set_view_3d(a.args[0] == "3d"))
        throw InputError(path_, static_cast<std::size_t>(a.line), "view 3d: " + no_heights(*viewer));
      return false;
    }
    if (v == "orbit" || v == "z-scale") {
      if (!viewer->can_view_3d())
        throw InputError(path_, static_cast<std::size_t>(a.line), v + ": " + no_heights(*viewer));
      Orbit orbit = viewer->orbit();
      if (v == "orbit") {
        orbit.azimuth_deg = std::strtod(a.args[0].c_str(), nullptr);
        orbit.elevation_deg = std::strtod(a.args[1].c_str(), nullptr);
      } else {
        orbit.z_scale = std::strtod(a.args[0].c_str(), nullptr);
      }
      viewer->set_orbit(orbit);
      return false;
    }
    if (v == "ui-scale") {
      viewer->ui_scale = *parse_ui_scale(a.args[0]);
      pending_.push_back({});  // the frame drawn with the new fonts
      return true;
    }
    if (v == "theme") {
      viewer->session().set_theme(*parse_theme(a.args[0]));
      pending_.push_back({});  // the panels' colours change with it
      return true;
    }
    if (v == "panels") {
      viewer->panels_hidden = a.args[0] == "hide";
      pending_.push_back({});  // the frame laid out without them
      return true;
    }
    if (v == "full-screen") {
      viewer->full_screen = a.args[0] == "on";
      pending_.push_back({});
      pending_.push_back({});  // the window system answers with the new size a frame later
      return true;
    }
    if (v == "select") {
      viewer->select_at({std::strtod(a.args[0].c_str(), nullptr), std::strtod(a.args[1].c_str(), nullptr)});
      return false;
    }
    if (is_edit_action(v)) {
      if (!workbench_) throw InputError(path_, static_cast<std::size_t>(a.line), "'" + v + "': no workbench here");
      run_edit_action(a, *workbench_, viewer ? &viewer->session() : nullptr, path_);
      if (v == "save" || v == "save-recipe") return false;
      pending_.push_back({});  // the frame that shows the new mesh (made before it)
      return true;
    }
    if (v == "sync" || v == "difference") {
      CompareView* compare = viewer->compare();
      if (!compare)
        throw InputError(path_, static_cast<std::size_t>(a.line),
                         v + ": only for runs side by side (meshstep view A.mslog B.mslog [C.mslog D.mslog])");
      if (v == "sync") compare->set_sync_mode(*parse_sync_mode(a.args[0]));
      else compare->difference = a.args[0] == "on";
      return false;
    }
    if (v == "compare-with") {
      std::string words;
      for (const std::string& w : a.args) words += (words.empty() ? "" : " ") + w;
      viewer->compare_words = words;
      pending_.push_back({});  // the frame on which the loop starts the run
      return true;
    }
    if (v == "wait" || v == "settle") return false;
    if (v == "check") {
      viewer->invariants().start(viewer->session().log() ? viewer->session().log()->path() : std::string());
      viewer->invariants().wait();
      return false;
    }
    if (v == "quit") {
      quit_ = true;
      return true;
    }
    (void)io;
    throw InputError(path_, static_cast<std::size_t>(a.line), "cannot run '" + v + "'");
  }

  const std::vector<ScriptAction>& actions_;
  std::string path_;
  std::size_t next_ = 0;
  std::uint64_t frames_left_ = 0;
  std::string live_state_;
  bool watching_ = false;
  bool stop_playing_ = false, pause_now_ = false;
  bool quit_ = false;
  std::vector<Input> pending_;
  const ScriptAction* capture_ = nullptr;
  int held_key_ = -1;
  WorkbenchHost* workbench_ = nullptr;
  float mouse_x_ = 0, mouse_y_ = 0;
  // `wait-until` (its action) or `wait-input`: until when the real input is the viewer's.
  bool waiting_ = false;
  const ScriptAction* wait_for_ = nullptr;
  std::chrono::steady_clock::time_point wait_end_{};
};

}  // namespace meshstep::viewer
