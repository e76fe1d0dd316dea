#include "viewer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare_view.hpp"
#include "imgui_gl.hpp"
#include "edit_canvas.hpp"
#include "keys.hpp"
#include "meshstep/scene/layout.hpp"
#include "panel_style.hpp"
#include "ui_look.hpp"
#include "workbench_host.hpp"

namespace meshstep::viewer {

namespace {

constexpr float kTimelineHeight = 122.0f;
// How far a drag on the 3D canvas turns the orbit: a canvas's width is about a full turn.
constexpr double kDegreesPerPixel = 0.5;
// The box every vertex of the run lies in: a camera fitted to it holds still while the
// mesh grows, as an exported animation does.
BBox run_box(Session& session) {
  BBox box;
  if (const replay::LogReader* log = session.log()) {
    for (const replay::VertexInfo& v : log->vertices())
      if (v.event != kNone) box.add(v.point);
    if (!box.empty()) return box;
  }
  return session.scene().bounds;
}

}  // namespace

Viewer::Viewer(std::unique_ptr<Session> session, const CanvasOptions& canvas)
    : session_(std::move(session)), view3d_(session_->log()), canvas_backend_(canvas.backend) {
  const replay::LogReader* log = session_->log();
  if (!log) return;
  angle_bound_ = log->run().min_angle.value_or(0.0);
  const bool big = log->vertices().size() > kCanvasWorkerVertices;
  if (canvas.mode == CanvasMode::worker || (canvas.mode == CanvasMode::automatic && big)) {
    worker_ = std::make_unique<CanvasWorker>(log->path(), canvas.backend);
    session_->defer_pictures(true);
  } else {
    start_background_jobs();
  }
}

// The history's index and the plots read the whole log on threads of their own. With a
// canvas worker they wait for its first picture: on two cores, they would slow it down.
void Viewer::start_background_jobs() {
  if (background_started_) return;
  background_started_ = true;
  history_.build(session_->log()->path());
  plots_.build(session_->log()->path(), angle_bound_);
}

void Viewer::apply(const Settings& s) {
  session_->set_color_by(s.color_by);
  session_->set_theme(s.theme);
  for (std::size_t i = 0; i < scene::kLayerCount; ++i)
    session_->set_layer(static_cast<scene::Layer>(i), s.layers.has(static_cast<scene::Layer>(i)));
  session_->playback().speed = std::clamp(s.speed, Playback::kMinSpeed, Playback::kMaxSpeed);
  session_->playback().unit = s.unit;
  follow = s.follow;
  timeline_marks = s.timeline_marks;
  side_panel_width_ = s.side_panel_width;
  explain_open_ = s.explain_open;
  layers_open_ = s.layers_open;
  stats_open_ = s.stats_open;
  code_open_ = s.code_open;
  ui_scale = s.ui_scale;
  view3d_.set_orbit(s.orbit);
  prefer_3d_ = s.view_3d;
  // Quietly: the settings ask for 3D whenever a terrain's run is open.
  if (view3d_.on() != (s.view_3d && view3d_.available())) set_view_3d(s.view_3d && view3d_.available());
}

void Viewer::capture(Settings& s) const {
  s.color_by = session_->options().color_by;
  s.theme = session_->options().theme;
  s.layers = session_->options().layers;
  s.speed = session_->playback().speed;
  s.unit = session_->playback().unit;
  s.follow = follow;
  s.timeline_marks = timeline_marks;
  s.side_panel_width = side_panel_width_;
  s.explain_open = explain_open_;
  s.layers_open = layers_open_;
  s.stats_open = stats_open_;
  s.code_open = code_open_;
  s.ui_scale = ui_scale;
  // A run without heights says nothing about the 3D view: the wish is kept for the next.
  s.view_3d = view3d_.available() ? view3d_.on() : prefer_3d_;
  s.orbit = view3d_.orbit();
}

bool Viewer::set_view_3d(bool on) {
  if (on == view3d_.on()) return true;
  if (on && !view3d_.available()) {
    say(session_->log() ? "3D view: this run has no heights (a terrain's run has: meshstep terrain GRID --record LOG)"
                        : "3D view: only for a terrain's recorded run (meshstep terrain GRID --record LOG)");
    return false;
  }
  view3d_.set_on(on);
  prefer_3d_ = on;
  hovered_ = {};
  if (on) {
    // The 2D camera waits for the way back; the 3D one starts fitted.
    camera_2d_ = camera_;
    moved_2d_ = camera_moved_;
    camera_moved_ = false;
    fit_pending_ = true;
  } else {
    camera_ = camera_2d_;
    camera_moved_ = moved_2d_;
    if (!camera_moved_ || camera_.width() <= 1) fit_pending_ = true;
  }
  return true;
}

bool Viewer::set_orbit(const Orbit& orbit) {
  if (!view3d_.available()) {
    say("3D view: this run has no heights, so there is no orbit to turn");
    return false;
  }
  if (view3d_.set_orbit(orbit)) orbit_changed();
  return true;
}

bool Viewer::turn_orbit(double d_azimuth_deg, double d_elevation_deg) {
  Orbit next = view3d_.orbit();
  next.azimuth_deg += d_azimuth_deg;
  next.elevation_deg += d_elevation_deg;
  if (view3d_.available() && !view3d_.on()) {
    say("the orbit turns the 3D view: press V to see it");
    return false;
  }
  return set_orbit(next);
}

bool Viewer::scale_heights(double factor) {
  Orbit next = view3d_.orbit();
  next.z_scale *= factor;
  if (view3d_.available() && !view3d_.on()) {
    say("the heights' scale is the 3D view's: press V to see it");
    return false;
  }
  return set_orbit(next);
}

// A new orbit: the whole run fitted again, unless the person zoomed or panned; then the
// camera turns about the pivot, at the same zoom (view_3d.hpp says why).
void Viewer::orbit_changed() {
  if (!view3d_.on()) return;
  if (!camera_moved_) {
    if (camera_.width() > 1) fit_camera(camera_.width(), camera_.height());
    else fit_pending_ = true;
    return;
  }
  camera_ = scene::Camera(view3d_.pivot_on_screen(), camera_.pixels_per_unit(), camera_.width(), camera_.height());
}

// After a pan, a zoom or a follow: in 3D the pivot goes under the camera's new centre.
void Viewer::camera_changed_by_hand() {
  if (view3d_.on()) view3d_.aim(camera_);
}

const scene::Scene& Viewer::shown_scene() {
  if (!view3d_.on()) return session_->scene();
  // The worker's picture brings its lifted scene; until the first 3D one, the planar moment.
  if (worker_) return picture_in_3d_ ? worker_lifted_ : session_->scene();
  // The planar scene first: building it counts a build, which names the lift to keep.
  const scene::Scene& planar = session_->scene();
  scene::Scene& lifted = view3d_.lifted(planar, session_->scene_builds(),
                                        max_vertex_markers_for(camera_.width(), camera_.height()));
  lifted.visible = session_->options().layers;
  return lifted;
}

void Viewer::say(const char* text) {
  notice_ = text;
  notice_seconds_ = 4.0;
}

void Viewer::notify(const std::string& text) { say(text.c_str()); }

void Viewer::scale_ui(int steps) {
  const float next = step_ui_scale(ui_scale, steps);
  if (next == ui_scale) say(steps > 0 ? "UI scale: 3 is the largest" : "UI scale: 0.75 is the smallest");
  ui_scale = next;
}

void Viewer::toggle_high_contrast() {
  session_->set_theme(session_->options().theme == scene::Theme::high_contrast ? scene::Theme::light
                                                                               : scene::Theme::high_contrast);
}

void Viewer::cycle_color_by(int direction) {
  if (view3d_.on()) say("in 3D the surface is coloured by its heights: the colouring shows in 2D (V)");
  const int n = static_cast<int>(scene::ColorBy::count_);
  const int now = static_cast<int>(session_->options().color_by);
  session_->set_color_by(static_cast<scene::ColorBy>(((now + direction) % n + n) % n));
}

void Viewer::toggle_layer(scene::Layer layer) { session_->set_layer(layer, !session_->layer(layer)); }

void Viewer::fit_camera(int width, int height) {
  const scene::Scene& s = shown_scene();
  if (view3d_.on()) {
    // The run's box as the orbit sees it: still while stepping, new with each turn.
    camera_ = scene::Camera::fit(view3d_.run_box(), width, height, scene::layout(s, width, height).margins);
    view3d_.center_pivot();
    view3d_.aim(camera_);
  } else {
    scene::Margins margins = scene::layout(s, width, height).margins;
    if (tour_) margins.top += 30.0 * ui_scale;  // the tour's row of buttons, under the caption
    camera_ = scene::Camera::fit(fit_box_ ? *fit_box_ : run_box(*session_), width, height, margins);
  }
  fit_pending_ = false;
  camera_moved_ = false;
}

// Keeps the faces the current step changed in view: pans when they leave the middle 80% of
// the canvas, and zooms out when they do not fit.
void Viewer::follow_step() {
  // Just after switching to 3D, the worker's picture (and its points) may still be planar.
  if (view3d_.on() && worker_ && !picture_in_3d_) return;
  const scene::Scene& s = shown_scene();
  BBox box;
  for (const std::uint32_t t : s.highlighted)
    if (t < s.mesh.triangles.size())
      for (const std::uint32_t v : s.mesh.triangles[t])
        if (v < s.mesh.points.size()) box.add(s.mesh.points[v]);
  if (box.empty()) return;
  const BBox view = camera_.visible();
  const double mx = 0.1 * (view.hi.x - view.lo.x), my = 0.1 * (view.hi.y - view.lo.y);
  const bool inside = box.lo.x >= view.lo.x + mx && box.hi.x <= view.hi.x - mx && box.lo.y >= view.lo.y + my &&
                      box.hi.y <= view.hi.y - my;
  if (inside) return;
  const double need = std::max((box.hi.x - box.lo.x) / (0.8 * (view.hi.x - view.lo.x)),
                               (box.hi.y - box.lo.y) / (0.8 * (view.hi.y - view.lo.y)));
  const double scale = need > 1.0 ? camera_.pixels_per_unit() / need : camera_.pixels_per_unit();
  camera_ = scene::Camera({0.5 * (box.lo.x + box.hi.x), 0.5 * (box.lo.y + box.hi.y)}, scale, camera_.width(),
                          camera_.height());
  camera_changed_by_hand();
}

void Viewer::fit_box(std::optional<BBox> box) {
  fit_box_ = box;
  fit_pending_ = true;
}

bool Viewer::start_quiz(std::optional<teach::QuestionKind> kind, std::string& why) {
  auto quiz = std::make_unique<QuizMode>();
  if (quiz_) quiz_->stop(*this);
  quiz_.reset();
  if (!quiz->start(*this, kind, why)) return false;
  quiz_ = std::move(quiz);
  return true;
}

void Viewer::stop_quiz() {
  if (quiz_) quiz_->stop(*this);
  quiz_.reset();
}

void Viewer::handle_keys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;
  for (const KeyAction& action : key_actions()) {
    if (!ImGui::IsKeyPressed(action.chord.key, true)) continue;
    if (action.chord.shift != io.KeyShift || action.chord.ctrl != io.KeyCtrl) continue;
    action.run(*this);
  }
}

void Viewer::frame(int width, int height, double seconds) {
  handle_keys();
  session_->advance(seconds);
  // The quiz's words take the caption's band while it is on.
  if (tour_ && !quiz_) tour_->update(*this);
  notice_seconds_ = std::max(0.0, notice_seconds_ - seconds);

  window_width_ = width;
  window_height_ = height;
  // The canvas's words grow with the panels'; the fit leaves them their room again. A
  // canvas that grew to the window (Tab, F11) is filled again too, unless the person moved
  // the camera.
  if (session_->options().text_scale != ui_scale) {
    session_->set_text_scale(ui_scale);
    if (!camera_moved_) fit_pending_ = true;
  }
  if (fitted_for_ != std::pair(panels_hidden, full_screen)) {
    fitted_for_ = {panels_hidden, full_screen};
    if (!camera_moved_) fit_pending_ = true;
  }
  // The panels grow with the UI scale, as their text does; hidden (Tab), the canvas is the
  // whole window.
  const float side = panels_hidden ? 0.0f : std::min(side_panel_width_ * ui_scale, 0.4f * static_cast<float>(width));
  const bool timeline_shown = session_->has_timeline() && !panels_hidden;
  const float timeline = timeline_shown ? std::min(kTimelineHeight * ui_scale, 0.4f * static_cast<float>(height)) : 0.0f;
  const float canvas_w = std::max(1.0f, static_cast<float>(width) - side);
  const float canvas_h = std::max(1.0f, static_cast<float>(height) - timeline);
  if (compare_) compare_->draw(0, 0, canvas_w, canvas_h);
  else draw_canvas(0, 0, canvas_w, canvas_h);
  if (!panels_hidden) draw_side_panel(canvas_w, 0, side, static_cast<float>(height));
  if (timeline_shown) draw_timeline(0, canvas_h, canvas_w, timeline);
  if (help_open) draw_help();
}

void Viewer::post_canvas_request() {
  CanvasRequest wanted = CanvasRequest::planar(session_->cursor_info().position, session_->options(), camera_);
  wanted.in_3d = view3d_.on();
  wanted.orbit = view3d_.orbit();
  worker_->request(wanted);
}

// A finished picture: its moment becomes the session's scene and words, its pixels the
// canvas's texture.
void Viewer::show_worker_picture() {
  session_->adopt(picture_.moment);
  stats_ = picture_.stats;
  picture_texture_.upload(picture_.image);
  ++canvas_renders_;
  // Its lifted scene, swapped so that both keep their buffers. The first 3D picture may ask
  // for a new fit: before it, the fit left room for the planar moment's caption and legend.
  const bool was_3d = picture_in_3d_;
  picture_in_3d_ = picture_.request.in_3d;
  if (picture_in_3d_) std::swap(worker_lifted_, picture_.lifted);
  if (picture_in_3d_ && !was_3d && view3d_.on() && !camera_moved_) fit_pending_ = true;
  if (!has_picture_) {
    has_picture_ = true;
    // The first fit had no caption or legend to leave room for.
    if (!camera_moved_) fit_pending_ = true;
    start_background_jobs();
  }
}

void Viewer::settle_canvas() {
  if (compare_) {
    compare_->settle();
    return;
  }
  if (!worker_) return;
  if (camera_.width() <= 1) {  // no frame yet: there is no canvas to wait for
    start_background_jobs();
    return;
  }
  // The first picture may ask for a new fit (its caption and legend take room): once more.
  for (int round = 0; round < 2; ++round) {
    post_canvas_request();
    worker_->wait_until_drawn();
    if (worker_->take(picture_)) show_worker_picture();
    if (!fit_pending_) return;
    fit_camera(camera_.width(), camera_.height());
  }
}

void Viewer::draw_canvas(float x, float y, float w, float h) {
  place(x, y, w, h);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  // Once there is a picture it covers the whole canvas: no background under it.
  const bool covered = !worker_ || has_picture_;
  ImGui::Begin("canvas", nullptr,
               kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                   ImGuiWindowFlags_NoScrollWithMouse | (covered ? ImGuiWindowFlags_NoBackground : 0));
  const int width = static_cast<int>(w), height = static_cast<int>(h);
  canvas_rect_ = ImVec4(x, y, w, h);
  if (fit_pending_ || camera_.width() != width || camera_.height() != height) {
    if (fit_pending_ || camera_.width() <= 1) {
      fit_camera(width, height);
    } else if (keep_corner_) {
      const Point corner = camera_.to_world({0.0, 0.0});
      camera_.resize(width, height);
      const Point moved = camera_.to_world({0.0, 0.0});
      camera_.pan((moved.x - corner.x) * camera_.pixels_per_unit(), (corner.y - moved.y) * camera_.pixels_per_unit());
    } else {
      camera_.resize(width, height);
    }
  }
  if (follow && session_->playback().playing) follow_step();

  if (worker_) {
    if (const std::string why = worker_->error(); !why.empty()) {
      // The worker could not start or draw: this thread draws from now on.
      std::fprintf(stderr, "meshstep view: %s; drawing on the main thread\n", why.c_str());
      worker_.reset();
      session_->defer_pictures(false);
      start_background_jobs();
    }
  }
  if (worker_) {
    post_canvas_request();
    if (worker_->take(picture_)) show_worker_picture();
    if (has_picture_) opaque_image(picture_texture_.id(), ImVec2(w, h));
    else ImGui::InvisibleButton("##canvas", ImVec2(w, h));
  } else {
    const scene::Scene& shown = shown_scene();
    const Drawn now{session_->scene_builds(), shown.visible.bits(), camera_.center().x, camera_.center().y,
                    camera_.pixels_per_unit(), width, height, view3d_.on(), view3d_.orbit(), shown.text_scale};
    if (!(now == drawn_)) {
      renderer_.render(shown, camera_);
      drawn_ = now;
      ++canvas_renders_;
    }
    opaque_image(texture_id(renderer_.texture()), ImVec2(w, h));
  }
  const bool canvas_hovered = ImGui::IsItemHovered();
  // Edit mode (edit_canvas.hpp): the left button edits, the middle one pans.
  const bool editing = workbench && workbench->editing && !view3d_.on();
  if (worker_ && worker_->drawing()) draw_drawing_badge(x, y);
  else if (workbench && workbench->remeshing_live()) draw_remeshing_badge(x, y);
  if (notice_shown()) draw_notice(x, y);
  // The tour's row, under the caption's band.
  if (tour_) tour_->draw(*this, x + 10.0f, y + 40.0f * ui_scale, w - 20.0f);
  if (quiz_) quiz_->draw(*this, x, y, w);

  // 2D: drag to pan. 3D: drag to turn the orbit, right-drag to pan. The wheel zooms at the
  // pointer in both.
  const ImGuiIO& io = ImGui::GetIO();
  refresh_selection();
  const bool in_3d = view3d_.on();
  if (canvas_hovered) {
    const ImVec2 mouse = io.MousePos;
    const Point at{mouse.x - x, mouse.y - y};
    if (io.MouseWheel != 0.0f) {
      camera_.zoom_at(at, std::pow(1.2, static_cast<double>(io.MouseWheel)));
      camera_moved_ = true;
      camera_changed_by_hand();
    }
    const bool moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
    if (moved && ImGui::IsMouseDragging(editing ? ImGuiMouseButton_Middle : ImGuiMouseButton_Left, 0.0f)) {
      // Dragging right turns the near side of the surface right; down looks more from above.
      if (in_3d) {
        turn_orbit(-kDegreesPerPixel * io.MouseDelta.x, kDegreesPerPixel * io.MouseDelta.y);
      } else {
        camera_.pan(io.MouseDelta.x, io.MouseDelta.y);
        camera_moved_ = true;
      }
    }
    if (moved && in_3d && ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f)) {
      camera_.pan(io.MouseDelta.x, io.MouseDelta.y);
      camera_moved_ = true;
      camera_changed_by_hand();
    }
    // Hover: looked up again only when the pointer moves, and not in huge meshes (a scan).
    if (moved && session_->scene().mesh.triangles.size() <= 200000) pick_under(at, hovered_);
    // A click (pressed and released without a drag) selects.
    if (!editing && ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 9.0f) {
      if (quiz_ && quiz_->asking() && !in_3d) {
        quiz_->answer(*this, camera_.to_world(at));
      } else if (in_3d) {
        Picked picked;
        pick_under(at, picked);
        select(picked);
      } else {
        select_at(camera_.to_world(at));
      }
    }
  } else {
    hovered_ = {};
  }
  draw_selection_overlay(x, y);
  if (editing) edit_canvas(*workbench, camera_, x, y, canvas_hovered);
  ImGui::End();
  ImGui::PopStyleVar(2);
}

// While the worker draws: which step the canvas shows and which it is drawing, in the
// canvas's corner (or its middle before the first picture).
void Viewer::draw_drawing_badge(float x, float y) {
  const replay::LogReader& log = *session_->log();
  const std::uint64_t wanted = session_->cursor_info().step;
  char text[96];
  if (has_picture_) {
    std::snprintf(text, sizeof text, "showing step %llu, drawing step %llu...",
                  static_cast<unsigned long long>(replay::step_at(log, session_->shown_position()).step),
                  static_cast<unsigned long long>(wanted));
  } else {
    std::snprintf(text, sizeof text, "replaying the run to step %llu...", static_cast<unsigned long long>(wanted));
  }
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text);
  const ImVec2 at = has_picture_ ? ImVec2(x + 10.0f, y + 10.0f)
                                 : ImVec2(x + 0.5f * (canvas_rect_.z - size.x), y + 0.5f * canvas_rect_.w);
  draw.AddRectFilled(ImVec2(at.x - 6.0f, at.y - 4.0f), ImVec2(at.x + size.x + 6.0f, at.y + size.y + 4.0f),
                     IM_COL32(30, 30, 30, 200), 4.0f);
  draw.AddText(at, IM_COL32(255, 255, 255, 255), text);
}

// While the workbench's re-meshing runs live: what the canvas shows meanwhile, in its corner.
void Viewer::draw_remeshing_badge(float x, float y) {
  char text[160];
  std::snprintf(text, sizeof text, "re-meshing the edited input in meshstep: %.1f s (the last mesh stays until it ends)",
                workbench->live_seconds());
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text);
  const ImVec2 at(x + 10.0f, y + 10.0f);
  draw.AddRectFilled(ImVec2(at.x - 6.0f, at.y - 4.0f), ImVec2(at.x + size.x + 6.0f, at.y + size.y + 4.0f),
                     IM_COL32(30, 30, 30, 200), 4.0f);
  draw.AddText(at, IM_COL32(255, 255, 255, 255), text);
}

// Why a key did nothing, at the canvas's bottom, fading out over its last second.
void Viewer::draw_notice(float x, float y) {
  const float alpha = static_cast<float>(std::min(1.0, notice_seconds_));
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  const ImVec2 size = ImGui::CalcTextSize(notice_.c_str());
  const ImVec2 at(x + 0.5f * (canvas_rect_.z - size.x), y + canvas_rect_.w - size.y - 20.0f);
  draw.AddRectFilled(ImVec2(at.x - 8.0f, at.y - 5.0f), ImVec2(at.x + size.x + 8.0f, at.y + size.y + 5.0f),
                     IM_COL32(30, 30, 30, static_cast<int>(220 * alpha)), 4.0f);
  draw.AddText(at, IM_COL32(255, 255, 255, static_cast<int>(255 * alpha)), notice_.c_str());
}

void Viewer::draw_help() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.94f);
  // No taller than the window: at 1024x640 the list ran off its bottom (the edit keys and
  // the mouse's lines unseen); it scrolls instead.
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(io.DisplaySize.x * 0.98f, io.DisplaySize.y * 0.96f));
  ImGui::Begin("Keys (? or F1 to close)", &help_open,
               ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
  // Two pairs of columns (key, what it does), filled row by row.
  if (ImGui::BeginTable("keys", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const KeyAction& a : key_actions()) {
      if (!a.what) continue;  // one line stands for a family (bookmarks 1-9)
      ImGui::TableNextColumn();
      const bool digit = a.chord.key >= '1' && a.chord.key <= '9';
      ImGui::TextColored(heading_color(), "%s", digit ? (a.chord.ctrl ? "Ctrl+1..9" : "1..9") : a.keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(a.what);
    }
    ImGui::EndTable();
  }
  ImGui::TextUnformatted("Drag the canvas to pan, turn the wheel to zoom at the pointer; drag the timeline to scrub.");
  ImGui::TextUnformatted("In 3D (a terrain's run, V): drag to turn the view, right-drag to pan, the wheel zooms.");
  ImGui::TextUnformatted("In edit mode (E): click to add, drag a point to move it, right-click to delete, middle-drag to pan;");
  ImGui::TextUnformatted("the region tool (B, Shift+B) drags a box, or draws a lasso from press to release, to refine.");
  ImGui::End();
}

void Viewer::show_side_by_side(SideBySide runs) {
  if (runs.runs.size() < 2) return;
  compare_ = std::make_unique<CompareView>(*this, std::move(runs), canvas_backend_);
  fit_pending_ = true;
}

void Viewer::toggle_difference() {
  if (compare_) compare_->difference = !compare_->difference;
  else say("difference overlay: open two to four runs side by side (meshstep view A.mslog B.mslog)");
}

scene::Image Viewer::canvas_picture() {
  if (worker_) {
    settle_canvas();
    return picture_.image;
  }
  renderer_.render(shown_scene(), camera_);
  drawn_ = Drawn{};
  return renderer_.read_pixels();
}

}  // namespace meshstep::viewer
