// The viewer's frame: the canvas (the renderer's picture of the scene at the cursor), the
// timeline, the explain panel, layers and colours, statistics, and the `?` overlay of keys,
// all immediate-mode Dear ImGui. It needs a current GL context and ImGui context; who made
// them (a GLFW window, or EGL/OSMesa off screen for scripts) is the host's business.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>

#include "meshstep/scene/camera.hpp"
#include "render/renderer.hpp"
#include "element_index.hpp"
#include "export_job.hpp"
#include "inspector.hpp"
#include "invariant_job.hpp"
#include "pseudocode.hpp"
#include "run_plots.hpp"
#include "session.hpp"
#include "settings.hpp"
#include "timeline.hpp"

namespace meshstep::viewer {

struct Stats {
  std::size_t vertices = 0, triangles = 0, steiner = 0;
  double min_angle = 0.0, max_angle = 0.0;
  std::array<float, 18> histogram{};  // smallest angles, 0-60 degrees in 18 bins
};

class Viewer {
 public:
  explicit Viewer(std::unique_ptr<Session> session);
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

  // UI state that keys and scripts change.
  bool help_open = false;
  bool follow = false;
  bool quit_requested = false;
  void request_fit() { fit_pending_ = true; }
  void cycle_color_by(int direction);
  void toggle_layer(scene::Layer layer);

  // Selects what is under a world point (a vertex within 8 pixels, else the triangle), as a
  // click on the canvas does; nothing there clears the selection.
  void select_at(Point world);
  // "triangle 12 40 7: angles 31.2 58.8 90.0, area 0.5, Lepp path of 3 to edge 4-9",
  // "vertex 33: Steiner, inserted by step 45 (refine)", or "" when nothing is selected.
  std::string selection_text();

  // Checks every step boundary of the log in the background ("check every step").
  InvariantJob& invariants() { return invariants_; }
  // The element history's index (built in the background when the log opens).
  const ElementIndex& history() const { return history_; }
  // The plots over the whole run (built in the background when the log opens).
  const RunPlots& plots() const { return plots_; }
  // The steps (1-based, as the caption counts) whose events name the selected vertex.
  std::vector<std::uint64_t> selected_vertex_steps() const;

  // The canvas's rectangle in the window (pixels), as the last frame laid it out.
  ImVec4 canvas_rect() const { return canvas_rect_; }
  // Renders the canvas alone (no UI) into an image, as `meshstep render` would.
  scene::Image canvas_picture();
  std::size_t canvas_renders() const { return canvas_renders_; }

 private:
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

  std::unique_ptr<Session> session_;
  render::Renderer renderer_;
  scene::Camera camera_;
  bool fit_pending_ = true;
  ImVec4 canvas_rect_{0, 0, 0, 0};

  // What the canvas texture shows, to draw it again only when something changed.
  struct Drawn {
    std::size_t scene_builds = SIZE_MAX;
    std::uint32_t layers = 0;
    double cx = 0, cy = 0, scale = 0;
    int width = 0, height = 0;
    friend bool operator==(const Drawn&, const Drawn&) = default;
  } drawn_;
  std::size_t canvas_renders_ = 0;

  Stats stats_;
  std::size_t stats_of_build_ = SIZE_MAX;
  char goto_text_[32] = "";
  float side_panel_width_ = 380.0f;
  double angle_bound_ = 0.0;  // the run's min_angle, 0 when it has none
  bool explain_open_ = true, layers_open_ = true, stats_open_ = true, code_open_ = true;
  // The pseudo-code line of the cursor's event, found again only when the cursor moves.
  CodeAt code_;
  // The inspector: what the pointer is over, and what was clicked (a triangle by its
  // vertices, found again in each new scene; a vertex by its id, which a log keeps).
  Picked hovered_, selected_;
  std::array<std::uint32_t, 3> selected_vertices_{};
  LeppPath lepp_;
  std::size_t selection_build_ = SIZE_MAX;
  std::string selection_text_;  // made again only when the selection or the scene changes
  std::vector<std::uint64_t> history_steps_;  // of the selected vertex
  std::pair<Picked, std::size_t> history_steps_of_{{}, SIZE_MAX};
  std::pair<Picked, std::size_t> selection_text_of_{{}, SIZE_MAX};  // the selection and scene it says
  InvariantJob invariants_;
  ElementIndex history_;
  RunPlots plots_;
  std::array<float, 6> plot_scales_{};  // min, max of each plot, found once when ready
  bool plot_scales_known_ = false;
  void draw_run_plots(float width);
  ExportJob export_job_;
  int export_range_[2] = {0, 0};
  std::string invariants_text_;  // the finished job's line, made once
  std::uint64_t code_position_ = UINT64_MAX;
  TimelineCache timeline_cache_;
};

}  // namespace meshstep::viewer
