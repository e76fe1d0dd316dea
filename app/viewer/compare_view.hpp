// Runs side by side (`meshstep view A.mslog B.mslog [C.mslog D.mslog]`): one canvas per run
// (side by side for two, 2x2 for three or four), each with its run's description over it,
// all at the moment the one timeline chose (compare_sync.hpp: the leading run is the
// viewer's session, the others follow it), seen through one camera (a pan or a zoom on any
// canvas moves them all), with the edges one mesh has and the other lacks marked when the
// difference overlay is on.
//
// Every run is drawn by a canvas worker of its own (canvas_worker.hpp), so that scrubbing
// four big runs never waits for a picture; the workers take turns (draw_turns.hpp), two
// drawing at a time while the window's frames keep up, one while they come late. The
// leader's pictures become the viewer's session's moments, as a single big run's do.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>

#include "canvas_worker.hpp"
#include "compare_sync.hpp"
#include "draw_turns.hpp"
#include "edge_difference.hpp"
#include "mesh_stats.hpp"
#include "picture_texture.hpp"
#include "run_plots.hpp"
#include "series_plot.hpp"
#include "session.hpp"

namespace meshstep::viewer {

class Viewer;

inline constexpr std::size_t kMaxRunsSideBySide = 4;
// How many of the runs' workers draw at once at most (DrawTurns), at the window's
// priority, while its frames keep to kSideBySideFrameSeconds; one while they come late
// (FramePace). Under load on 2 cores, two at once gave the timeline's run 2.3 times the new
// pictures a second of four at once below the window's priority (nice 5), for 0.76 times
// its frames (docs/viewer.md).
inline constexpr unsigned kDrawingAtOnce = 2;
inline constexpr double kSideBySideFrameSeconds = 1.0 / 30.0;

// Logs opened for side by side: the leader (the run with the most steps) apart, for the
// viewer's session, and the others in their places (the leader's slot empty).
struct SideBySide {
  std::unique_ptr<Session> leader;
  std::size_t leader_index = 0;
  std::vector<std::unique_ptr<Session>> runs;  // in the command line's order
};
// Throws InputError for a file that is not a valid log.
SideBySide open_side_by_side(const std::vector<std::string>& paths);

// The run's description in a few words ("offcenter, min angle 30, dcel"): the caption
// over its canvas.
std::string run_description(const replay::LogReader& log);

// The state's `runs` (scripted mode): one entry per run, in the command line's order, with
// its cursor, caption and statistics; one entry for a single run. Then the sync mode and
// the overlay. A JSON array, one run a line.
std::string runs_state_json(Viewer& viewer);

// The biggest log each run's worker keeps all writes of decoded, with `runs` side by side.
std::uint64_t keep_writes_bytes(std::size_t runs);

class CompareView {
 public:
  struct Pane {
    Session* session = nullptr;      // the viewer's (the leader) or `own`
    std::unique_ptr<Session> own;    // a follower's
    std::string description;
    std::vector<std::uint64_t> insertions;  // insertion_events of its log
    std::vector<std::pair<std::string, std::uint64_t>> phase_steps;
    std::unique_ptr<CanvasWorker> worker;
    CanvasPicture picture;
    PictureTexture texture;
    bool has_picture = false;
    std::uint64_t shown_position = UINT64_MAX;  // the moment its picture shows
    Stats stats;
    EdgeSet edges;                                // of the moment shown
    std::vector<std::array<Point, 2>> different;  // its edges the run compared with lacks
    RunPlots plots;
    bool plots_started = false;
    std::array<SeriesPlot, 2> plot_pictures;  // its triangles and smallest angle over the run
    ImVec4 rect{0, 0, 0, 0};  // its picture's rectangle in the window
  };

  CompareView(Viewer& viewer, SideBySide runs, const std::string& backend);

  std::size_t size() const { return panes_.size(); }
  const Pane& pane(std::size_t i) const { return panes_[i]; }
  std::size_t leader() const { return leader_; }
  // The run each canvas is compared with for the difference overlay: the first run's with
  // the second's, every other's with the first's.
  std::size_t compared_with(std::size_t i) const { return i == 0 ? 1 : 0; }

  SyncMode sync_mode() const { return mode_; }
  void set_sync_mode(SyncMode mode) { mode_ = mode; }
  bool difference = false;  // the overlay (D)

  // Moves every follower to the leader's moment.
  void sync();
  // The canvases in the rectangle (the window's canvas area), and the pointer's pans and
  // zooms on them.
  void draw(float x, float y, float w, float h);
  // Waits until every canvas shows its run's synced moment with the current camera.
  void settle();
  // The side panel's part: the sync mode, the overlay, the statistics in columns and the
  // histograms and plots on shared axes.
  void draw_panel(float width);
  // The other runs' plots are made (the leader's are the viewer's).
  bool plots_ready();
  // Some canvas has not drawn its latest request yet (its worker is busy, or its picture
  // not taken).
  bool drawing() const;

 private:
  void fit(int pane_w, int pane_h);
  void start_next_plots();
  void post(Pane& pane);
  bool take(Pane& pane);
  void differences();
  void draw_difference(const Pane& pane, ImDrawList& draw) const;

  // A row of the statistics' steps per phase: a phase any run has, its label, and each
  // run's steps in it (0 when it has none). Made once: the panel's frames allocate nothing.
  struct PhaseRow {
    std::string label;  // "  insert vertices"
    std::array<std::uint64_t, kMaxRunsSideBySide> steps{};
  };

  Viewer& viewer_;
  // Declared before the panes: their workers take turns with it until they stop.
  std::unique_ptr<DrawTurns> turns_;
  std::vector<Pane> panes_;
  std::vector<PhaseRow> phase_rows_;
  std::size_t leader_ = 0;
  SyncMode mode_ = SyncMode::step;
  bool differences_stale_ = true;
  int pane_w_ = 0, pane_h_ = 0;
  std::size_t next_plots_ = 0;
  FramePace pace_{kSideBySideFrameSeconds, kDrawingAtOnce};
  std::chrono::steady_clock::time_point last_frame_{};
  std::array<float, 4> plot_scales_{};  // the plots' shared value ranges, found once
  bool plot_scales_known_ = false;  // the first run whose plots are not ready yet
};

}  // namespace meshstep::viewer
