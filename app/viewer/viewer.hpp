// The viewer's frame: the canvas (the renderer's picture of the scene at the cursor), the
// timeline, the explain panel, layers and colours, statistics, and the `?` overlay of keys,
// all immediate-mode Dear ImGui. It needs a current GL context and ImGui context; who made
// them (a GLFW window, or EGL/OSMesa off screen for scripts) is the host's business.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <imgui.h>

#include "meshstep/scene/camera.hpp"
#include "render/gl_objects.hpp"
#include "render/renderer.hpp"
#include "canvas_worker.hpp"
#include "element_index.hpp"
#include "element_story.hpp"
#include "export_job.hpp"
#include "inspector.hpp"
#include "mesh_stats.hpp"
#include "invariant_job.hpp"
#include "picture_texture.hpp"
#include "meshstep/scene/pseudocode.hpp"
#include "run_plots.hpp"
#include "series_plot.hpp"
#include "session.hpp"
#include "settings.hpp"
#include "timeline.hpp"
#include "quiz_mode.hpp"
#include "tour_guide.hpp"
#include "view_3d.hpp"

namespace meshstep::viewer {

class WorkbenchHost;
class CompareView;
struct SideBySide;

// Who draws the canvas: this thread, or a worker of its own (canvas_worker.hpp), which the
// viewer chooses for runs of more than kCanvasWorkerVertices vertices (automatic).
enum class CanvasMode { automatic, this_thread, worker };
inline constexpr std::size_t kCanvasWorkerVertices = 20000;
struct CanvasOptions {
  CanvasMode mode = CanvasMode::automatic;
  std::string backend = "egl";  // the GL library of the UI's context: "egl" or "osmesa"
};

class Viewer {
 public:
  explicit Viewer(std::unique_ptr<Session> session, const CanvasOptions& canvas = {});
  ~Viewer();

  // One frame of UI for a window of width x height pixels; `seconds` since the last one.
  // Call between ImGui::NewFrame and ImGui::Render.
  void frame(int width, int height, double seconds);

  Session& session() { return *session_; }
  scene::Camera& camera() { return camera_; }
  const Stats& stats();

  // The options a person set last time (settings.hpp), and back.
  void apply(const Settings& settings);
  void capture(Settings& settings) const;

  // Set by the export panel: the host reads the next whole frame into this file.
  std::string window_capture_path;
  std::string export_status;  // what the last export wrote, or why it failed
  std::string window_title;   // the window's title, as the host shows it (for scripts' state)

  // Shows NEXT instead of the session shown, keeping the renderer, the panels and the
  // options (swap_session.cpp): the workbench's run after an edit. False (NEXT untouched)
  // when a new viewer is needed: a canvas worker's run, or runs side by side.
  bool swap_session(std::unique_ptr<Session>& next);
  // What of the run shown is slow to free, taken out for the caller to free on another
  // thread (disposal.hpp): the session and the canvas worker (which reads its own copy of
  // the log, with its own GL context). The jobs that read the session's log (the history's
  // index, the plots, the invariant check) are stopped first. The viewer is then only to be
  // destroyed.
  struct Leftovers {
    std::unique_ptr<CanvasWorker> worker;
    std::unique_ptr<Session> session;
  };
  Leftovers release_run();

  // The workbench (workbench_host.hpp), set by the loop: edit mode's keys, canvas overlay
  // and panel go through it. Null: no editing (tests of the viewer alone).
  WorkbenchHost* workbench = nullptr;
  // Shows what `camera` showed, with no fit: the workbench's next run keeps the view. The
  // world point at the canvas's top-left corner stays there when this run's canvas is of
  // another size (a run has a timeline under it, an input alone none), so that what is
  // under the pointer stays under it.
  void keep_camera(const scene::Camera& camera) {
    camera_ = camera;
    fit_pending_ = false;
    camera_moved_ = true;
    keep_corner_ = true;
  }

  // UI state that keys and scripts change.
  bool help_open = false;
  bool follow = false;
  bool quit_requested = false;
  MarkSet timeline_marks = MarkSet::defaults();  // the kinds the timeline marks
  void request_fit() { fit_pending_ = true; }
  // Presentation (ui_look.hpp): the UI scale the next frame is drawn at (the run's loop
  // rasterises the fonts again between frames), the panels hidden so that the canvas fills
  // the window (Tab), and full screen asked for (F11; the loop asks the host, and says here
  // when it cannot be).
  float ui_scale = 1.0f;
  bool panels_hidden = false;
  bool full_screen = false;
  void scale_ui(int steps);
  // The high-contrast theme on, or back to the light one (Shift+T).
  void toggle_high_contrast();
  // A line on the canvas for a few seconds: why something asked for did not happen.
  void notify(const std::string& text);
  // The window's size, as the last frame had it.
  int window_width() const { return window_width_; }
  int window_height() const { return window_height_; }
  void cycle_color_by(int direction);
  void toggle_layer(scene::Layer layer);

  // A guided tour (tour_guide.hpp), when one plays; null otherwise. Each frame updates it.
  TourGuide* tour() { return tour_.get(); }
  void set_tour(std::shared_ptr<TourGuide> tour) { tour_ = std::move(tour); }
  // The camera fits this world box (a tour stop's) instead of the run's; none: the run's.
  void fit_box(std::optional<BBox> box);
  // The quiz (quiz_mode.hpp), while it is on; null otherwise. A click on the canvas answers
  // its open question instead of selecting.
  QuizMode* quiz() { return quiz_.get(); }
  const QuizMode* quiz() const { return quiz_.get(); }
  // Starts it (false, and `why`, when the run has no such question after the cursor).
  bool start_quiz(std::optional<teach::QuestionKind> kind, std::string& why);
  void stop_quiz();

  // The 3D view of a terrain's run (view_3d.hpp). Switching it on for a run without heights
  // is refused: false, and the canvas says why (notice()). The orbit changes only where
  // there is a 3D view; without one the canvas says so too.
  bool can_view_3d() const { return view3d_.available(); }
  bool view_3d() const { return view3d_.on(); }
  bool set_view_3d(bool on);
  const Orbit& orbit() const { return view3d_.orbit(); }
  bool set_orbit(const Orbit& orbit);
  bool turn_orbit(double d_azimuth_deg, double d_elevation_deg);
  bool scale_heights(double factor);
  // What the canvas shows: the session's scene, or in 3D that scene lifted (its points are
  // then in the orbit's screen plane, as the camera's are).
  const scene::Scene& shown_scene();
  // A line the canvas shows for a few seconds: why a key did nothing.
  const std::string& notice() const { return notice_; }
  bool notice_shown() const { return notice_seconds_ > 0.0; }

  // Selects what is under a world point (a vertex within 8 pixels, else a segment within 5,
  // else the triangle), as a click on the canvas does; nothing there clears the selection.
  void select_at(Point world);
  // "triangle 12 40 7: angles 31.2 58.8 90.0, area 0.5, Lepp path of 3 to edge 4-9",
  // "vertex 33: Steiner, inserted by step 45 (refine)", "segment 14-9: ...", or "" when
  // nothing is selected.
  std::string selection_text();
  // What the element history's index says about the selection at the canvas's moment (its
  // events are the timeline's ticks); empty until the index is ready.
  const SelectionStory& selection_story();

  // Checks every step boundary of the log in the background ("check every step").
  InvariantJob& invariants() { return invariants_; }
  // The element history's index (built in the background when the log opens).
  const ElementIndex& history() const { return history_; }
  // The plots over the whole run (built in the background when the log opens).
  const RunPlots& plots() const { return plots_; }

  // The timeline's columns and marks, as the last frame counted them.
  const TimelineCache& timeline() const { return timeline_cache_; }
  // Scripts, before they look: the pass over the events for the timeline's marks ended and
  // counted.
  void settle_timeline_marks();

  // The canvas's rectangle in the window (pixels), as the last frame laid it out.
  ImVec4 canvas_rect() const { return canvas_rect_; }
  // Renders the canvas alone (no UI) into an image, as `meshstep render` would.
  scene::Image canvas_picture();
  std::size_t canvas_renders() const { return canvas_renders_; }
  // True when a worker draws the canvas; the canvas may then show an earlier moment than
  // the cursor's for a while (session().shown_position() says which).
  bool canvas_on_worker() const { return worker_ != nullptr; }
  bool canvas_drawing() const { return worker_ && worker_->drawing(); }
  // Waits until the canvas shows the cursor with the current options and camera (scripts
  // do, before they look). Returns at once when this thread draws the canvas.
  void settle_canvas();

  // Runs side by side (compare_view.hpp): the other runs of `meshstep view A B [C D]`, this
  // viewer's session leading them. Null for one run.
  void show_side_by_side(SideBySide runs);
  CompareView* compare() { return compare_.get(); }
  // The difference overlay on or off (D); with one run the canvas says it needs two.
  void toggle_difference();
  // "Compare with..." (compare_with.hpp): the refinement's words the person (or a script)
  // asked for; the run's loop takes them, runs the input again and shows both runs.
  std::string compare_words;

 private:
  friend class CompareView;  // it lays out the canvases, fits the shared camera, feeds the session
  void handle_keys();
  void draw_canvas(float x, float y, float w, float h);
  void draw_side_panel(float x, float y, float w, float h);
  void draw_timeline(float x, float y, float w, float h);
  void draw_transport();
  void draw_pseudocode();
  void draw_invariants();
  void draw_selection_panel();
  void draw_export();
  void draw_selection_overlay(float x, float y);
  void refresh_selection();
  void draw_timeline_bar(float height);
  void draw_help();
  void fit_camera(int width, int height);
  void follow_step();
  void start_background_jobs();
  void post_canvas_request();
  void show_worker_picture();
  void draw_drawing_badge(float x, float y);
  void draw_remeshing_badge(float x, float y);
  void draw_notice(float x, float y);
  void draw_view_controls();
  void say(const char* text);
  void orbit_changed();
  void camera_changed_by_hand();
  void pick_under(Point screen, Picked& picked);
  void select(const Picked& picked);

  std::unique_ptr<Session> session_;
  render::Renderer renderer_;
  scene::Camera camera_;
  bool fit_pending_ = true;
  bool keep_corner_ = false;  // keep_camera: the next resize keeps the top-left corner
  ImVec4 canvas_rect_{0, 0, 0, 0};
  int window_width_ = 0, window_height_ = 0;
  std::pair<bool, bool> fitted_for_{false, false};  // panels hidden, full screen: at the last fit

  // What the canvas texture shows, to draw it again only when something changed.
  struct Drawn {
    std::size_t scene_builds = SIZE_MAX;
    std::uint32_t layers = 0;
    double cx = 0, cy = 0, scale = 0;
    int width = 0, height = 0;
    bool in_3d = false;
    Orbit orbit;
    float text_scale = 1.0f;
    friend bool operator==(const Drawn&, const Drawn&) = default;
  } drawn_;
  std::size_t canvas_renders_ = 0;

  Stats stats_;
  std::size_t stats_of_build_ = SIZE_MAX;
  char goto_text_[32] = "";
  std::string goto_refusal_;  // why the go-to box's number was refused, shown over it
  float side_panel_width_ = 380.0f;
  double angle_bound_ = 0.0;  // the run's min_angle, 0 when it has none
  bool explain_open_ = true, layers_open_ = true, stats_open_ = true, code_open_ = true;
  // The pseudo-code line of the cursor's event, found again only when the cursor moves.
  scene::CodeAt code_;
  // The inspector: what the pointer is over, and what was clicked (a triangle by its
  // vertices, found again in each new scene; a vertex by its id, which a log keeps).
  Picked hovered_, selected_;
  std::vector<MeshEdge> hover_edges_;  // the scene's constrained edges, for hovering
  std::size_t hover_edges_build_ = SIZE_MAX;
  std::array<std::uint32_t, 3> selected_vertices_{};
  LeppPath lepp_;
  std::size_t selection_build_ = SIZE_MAX;
  std::string selection_text_;  // made again only when the selection or the scene changes
  // The selection's story, of the selection at a position with the index ready or not.
  SelectionStory story_;
  std::tuple<Picked, std::uint64_t, bool> story_of_{{}, UINT64_MAX, false};
  std::pair<Picked, std::size_t> selection_text_of_{{}, SIZE_MAX};  // the selection and scene it says
  InvariantJob invariants_;
  ElementIndex history_;
  RunPlots plots_;
  std::array<SeriesPlot, 3> run_plot_pictures_;  // the three plots of draw_run_plots
  std::array<float, 6> plot_scales_{};  // min, max of each plot, found once when ready
  bool plot_scales_known_ = false;
  void draw_run_plots(float width);
  ExportJob export_job_;
  int export_range_[2] = {0, 0};
  std::string invariants_text_;  // the finished job's line, made once
  std::uint64_t code_position_ = UINT64_MAX;
  TimelineCache timeline_cache_;
  TickStrip tick_strip_;  // the timeline's ticks of a long run
  // The canvas's worker (big runs), its last picture and the texture that shows it.
  std::unique_ptr<CanvasWorker> worker_;
  CanvasPicture picture_;
  PictureTexture picture_texture_;
  bool has_picture_ = false, background_started_ = false;
  bool camera_moved_ = false;  // by the person, since the last fit
  // The 3D view; the 2D camera, put back when the view goes back to 2D; whether the canvas's
  // worker picture is a 3D one (it is, once drawn, what the 3D overlays go over).
  View3d view3d_;
  scene::Camera camera_2d_;
  bool moved_2d_ = false;
  bool prefer_3d_ = false;  // asked for (settings), kept for the next terrain run opened
  scene::Scene worker_lifted_;
  bool picture_in_3d_ = false;
  std::string notice_;
  double notice_seconds_ = 0.0;
  std::string canvas_backend_;  // the GL library of the UI's context, for workers
  char compare_text_[160] = "";  // the "Compare with..." field
  std::shared_ptr<TourGuide> tour_;
  std::unique_ptr<QuizMode> quiz_;
  std::optional<BBox> fit_box_;
  // Last: destroyed first, as it refers to the session and the camera.
  std::unique_ptr<CompareView> compare_;
};

}  // namespace meshstep::viewer
