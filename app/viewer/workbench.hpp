// The workbench: an input being edited (pslg/pslg_editor.hpp) and the recipe that makes its
// mesh. After each edit the input is triangulated again and the recipe runs again, in this
// process and on the core's own path (`meshstep run`'s: refine_chain, or triangulate for a
// recipe of no operation), recorded into a log of its own that the viewer then shows as a
// run: mesh, statistics and timeline.
//
// Input the core refuses (coordinates outside the range rule, fewer than three vertices
// not on a line) gives no new mesh: the core's message is kept, with the element it names,
// for the canvas to draw beside it; the mesh shown stays the last good one. What the core
// only warns of (two vertices at one place, merged) and what it does in silence (a hole
// point that removes nothing) are kept in the same way, next to a mesh that was made.
//
// No GL, no ImGui: the scripts, the keys and the tests drive it alike.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "meshstep/pslg/pslg_editor.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "session.hpp"

namespace meshstep::viewer {

// A line the canvas draws next to an element of the input (none: the canvas's corner).
struct InputNotice {
  ElementRef element;
  std::string text;
  bool refused = false;  // the core refused the input (no mesh made), or only warned
};

// Where the core's message names an element of the input: "vertex 3", "hole point 1",
// "region point 2" or "segment 5", numbered from first_index; none when it names none.
ElementRef element_named(const std::string& message, int first_index);

// A recipe line as the panel shows it: each --region-polygon's list of coordinates replaced
// by "(lasso of N points)"; the rest as it is.
std::string recipe_label(const std::string& line);

class Workbench {
 public:
  // `file`: where Ctrl+S saves (empty: a new input, which needs Save as).
  Workbench(Pslg input, std::vector<Operation> recipe, std::string file);
  ~Workbench();  // removes its temporary files
  Workbench(const Workbench&) = delete;
  Workbench& operator=(const Workbench&) = delete;

  PslgEditor& editor() { return editor_; }
  const PslgEditor& editor() const { return editor_; }
  const std::vector<Operation>& recipe() const { return recipe_; }
  // Its operations in the recipe's words, made once (the panel draws them every frame).
  const std::vector<std::string>& recipe_lines() const { return recipe_lines_; }
  // The same lines as the panel lists them: a polygon written out (--region-polygon
  // X0,Y0,...) as "--region-polygon (lasso of N points)", which wraps at its spaces (the
  // numbers, wrapped in the middle, read badly). Made with the lines.
  const std::vector<std::string>& recipe_labels() const { return recipe_labels_; }
  const std::string& file() const { return file_; }
  // The title the viewer shows: the file, or "new input".
  std::string title() const;

  // The recipe's operations, changed (issue 27 items 3 and 4): appended (a region refined),
  // removed, moved up or down (by one), switched off or on. An operation switched off stays
  // in the list and is not run. Each makes the mesh stale. Indices out of range do nothing.
  void append_operation(Operation op);
  void remove_operation(std::size_t i);
  // Operation i becomes `op` (its line edited in the recipe panel, or `recipe edit`), keeping
  // its place and whether it is switched on.
  void replace_operation(std::size_t i, Operation op);
  void move_operation(std::size_t i, int direction);
  void switch_operation(std::size_t i, bool on);
  bool operation_on(std::size_t i) const { return i < enabled_.size() && enabled_[i]; }
  // The recipe file `meshstep run` reads: the operations switched on, one a line, in the
  // recipe's words (those switched off as comments). Written atomically; throws InputError,
  // also for a path that is the input's own file.
  void save_recipe(const std::string& path) const;
  std::string recipe_text() const;

  // Whether the input or the recipe changed since the mesh was last made (or refused).
  bool stale() const { return made_revision_ != editor_.revision() + recipe_revision_; }
  // Makes the mesh of the input as it is now. Returns the session to show: the new run, or
  // the input alone while there never was a good mesh; null when the core refused the
  // input and the last good mesh stays on screen. notices() then say why.
  std::unique_ptr<Session> remesh();

  // A bigger run goes live (issue 27): run by `meshstep` in a process of its own while the
  // window keeps drawing the last good mesh (workbench_host.hpp). It does when the last
  // re-meshing took more than kLiveCpuMs of processor time (a frame or two and more), or
  // when the last mesh or the input has more than kLiveVertices vertices (the first edit of
  // a big run: nothing was timed yet). Processor time, not the wall clock's: which way an
  // edit goes does not change with the machine's load.
  static constexpr double kLiveCpuMs = 50.0;
  static constexpr std::size_t kLiveVertices = 20000;
  bool goes_live() const;
  // The run the workbench starts from had this many vertices (its log's).
  void expect_vertices(std::size_t n) { last_vertices_ = n; }
  // The command of a live re-meshing of the input as it is now, PROGRAM first: `run RECIPE
  // INPUT` (`triangulate INPUT` for no operation) recording LOG, its --stats on its output.
  // The input and the recipe are written to the temporary folder; the mesh is no longer
  // stale.
  struct LiveCommand {
    std::vector<std::string> args;
    std::string log;
  };
  LiveCommand live_command(const std::string& program);
  // The live run's end, as remesh() returns: the session of its log, `opened` (the caller
  // opens it off the window's thread: log_opening.hpp; null with `open_error` when it could
  // not be read); null when the run was refused (notices() say why, in the core's words) and
  // the last good mesh stays.
  std::unique_ptr<Session> finish_live(const std::string& log, bool succeeded, const std::string& messages,
                                       const std::string& output, double cpu_seconds, double wall_ms,
                                       std::unique_ptr<Session> opened, const std::string& open_error);
  std::size_t live_runs() const { return live_runs_; }
  double last_cpu_ms() const { return cpu_ms_; }

  const std::vector<InputNotice>& notices() const { return notices_; }
  bool refused() const { return !notices_.empty() && notices_.front().refused; }
  std::size_t mesh_triangles() const { return mesh_triangles_; }  // of the last good mesh
  double remesh_ms() const { return remesh_ms_; }                  // the last remesh(), all of it
  std::size_t remeshes() const { return remeshes_; }

  // Saves the input to PATH (a .poly, written atomically), which becomes file(). Throws
  // InputError ("PATH: why").
  void save(const std::string& path);

 private:
  std::string temporary(const std::string& name) const;
  void find_idle_holes(const Pslg& input);

  PslgEditor editor_;
  std::vector<Operation> recipe_;
  std::vector<std::string> recipe_lines_, recipe_labels_;
  std::vector<bool> enabled_;          // per operation: run or switched off
  std::uint64_t recipe_revision_ = 0;  // goes up with every change of the recipe
  void recipe_changed();
  std::string file_;
  std::string folder_;  // this workbench's temporary folder
  std::uint64_t made_revision_ = UINT64_MAX;
  std::vector<InputNotice> notices_;
  std::size_t mesh_triangles_ = 0, remeshes_ = 0;
  double remesh_ms_ = 0.0;
  double cpu_ms_ = 0.0;              // processor time of the last re-meshing
  std::size_t last_vertices_ = 0;    // vertices of the last mesh made
  std::size_t live_runs_ = 0;
  std::unique_ptr<Session> shown(const std::string& log);  // opened at its end, as the new mesh
  // The same, for a log opened already (at its end).
  std::unique_ptr<Session> shown(std::unique_ptr<Session> session, const std::string& log);
  bool has_mesh_ = false;
  std::string shown_log_;  // the log of the session last returned
};

}  // namespace meshstep::viewer
