// Where the viewer's loop keeps its workbench (workbench.hpp): started by New (Ctrl+N, the
// start page, a script's `new`) or by Edit (E) on the run shown, whose input and recipe it
// takes; and the edit mode, in which the canvas takes clicks as edits. The loop asks it,
// before each frame, for a new session to show when an edit made the mesh stale.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "edit_canvas.hpp"
#include "live_run.hpp"
#include "log_opening.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "meshstep/scene/camera.hpp"
#include "session.hpp"
#include "workbench.hpp"

namespace meshstep::viewer {

class WorkbenchHost;
// The `state` fields of the workbench, each "  \"key\": value,\n": "editing"; "input" (its
// counts: vertices, segments, holes, regions); "recipe" (its operations' lines); "refusal"
// (the core's words when it refused the input, else null); "input_notices" (every notice:
// element, index and text); "mesh_triangles" (of the last good mesh); "undo_depth";
// "edit_message"; "input_file".
std::string workbench_state_fields(const WorkbenchHost& host);

class WorkbenchHost {
 public:
  Workbench* bench() { return bench_.get(); }
  const Workbench* bench() const { return bench_.get(); }
  // Edit mode: the canvas draws the input over the mesh and takes clicks as edits.
  bool editing = false;

  // An empty input (keeping the recipe of a workbench already open). Edit mode on.
  void start_new();
  // The input of the run `session` shows and its recipe (`known`: the operation the input
  // was opened with, when the loop knows it; else recipe_of its log). Returns "" or why it
  // cannot be (a mesh with no input file, a log whose input is gone). Edit mode on.
  std::string start_from(const Session& session, const std::optional<std::vector<Operation>>& known = std::nullopt);
  // The recipe an input was opened with (the loop knows it: the command line's or the
  // start page's options), used by start_from for a run of that input rather than what its
  // log's header keeps.
  void know_recipe(std::string input, std::vector<Operation> recipe) {
    known_input_ = std::move(input);
    known_recipe_ = std::move(recipe);
  }
  // E: edit mode on (starting from the session when there is no workbench yet) or off.
  std::string toggle(const Session* session);

  // The session to show after an edit (workbench.hpp: remesh), or null: nothing changed,
  // or the core refused the input and the last good mesh stays. A bigger run goes live
  // (Workbench::goes_live): `meshstep` runs it in a process of its own, null is returned
  // meanwhile (the last good mesh stays on screen, the frames stay short), and its session
  // when it has ended; an edit made meanwhile stops it and starts another. With
  // `take_ended_live` false a live run that has ended is left for a later call (scripts
  // take it only when they look: what they see does not depend on the machine's speed).
  std::unique_ptr<Session> take_session(bool take_ended_live = true);
  // Whether the live re-meshing goes: its process still runs, or its log is being opened
  // (on a thread of its own: log_opening.hpp; the window keeps drawing the last mesh).
  bool live_running() { return live_ && (live_->running() || (opening_ && !opening_->ready())); }
  // The opening of the ended live run's log, while it goes (null else): for tests.
  const LogOpening* live_opening() const { return opening_.get(); }
  // Whether a live re-meshing goes (or has ended, its mesh not yet taken); for how long.
  bool remeshing_live() const { return live_ != nullptr; }
  double live_seconds() const { return live_ ? live_->seconds() : 0.0; }
  // Live re-meshings stopped by a newer edit.
  std::size_t live_cancelled() const { return live_cancelled_; }
  // Scripts, before they look: the live re-meshing has ended and its log is open
  // (take_session then has it).
  void wait_live();
  // Whether the viewer now shows the workbench's run (the loop carries its camera over).
  bool showing = false;
  // Whether every point of the input is in the camera's view: the next run keeps the view
  // then (a click is always in view: the picture does not jump under the pointer), else
  // it is fitted again (a script's coordinates, or an empty input).
  bool in_view(const scene::Camera& camera) const;
  // The canvas tool's state (edit_canvas.hpp).
  EditCanvasState tool;
  // Why the last edit asked for was refused (an EditRefused's words), or what was saved;
  // the edit panel shows it and `state` reports it.
  std::string message;
  void say(std::string text) { message = std::move(text); }
  // Ctrl+S: saves to the workbench's file; without one (a new input), says that Save as
  // (the panel's field) needs a name. Returns what it said.
  std::string save(const std::string& path = "");
  // Undo and redo (Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y); the polyline being drawn ends.
  void undo();
  void redo();

 private:
  // Declared before the workbench: the run ends (and its files go) before the workbench's
  // folder is removed.
  std::unique_ptr<Workbench> bench_;
  std::unique_ptr<LiveRun> live_;
  // The ended live run's log, being opened off the window's thread; and openings a newer
  // edit made useless, kept until their threads end (joined then, not on the window's
  // thread while they read). Declared after the run: they end before it (and its files).
  std::unique_ptr<LogOpening> opening_;
  std::vector<std::unique_ptr<LogOpening>> abandoned_;
  void reap_abandoned();
  // The ended live run's log being opened (when it succeeded): started once.
  void start_opening();
  std::size_t live_cancelled_ = 0;
  std::string known_input_;
  std::vector<Operation> known_recipe_;
};

}  // namespace meshstep::viewer
