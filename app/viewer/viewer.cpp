#include "viewer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "imgui_gl.hpp"
#include "keys.hpp"
#include "meshstep/scene/layout.hpp"
#include "panel_style.hpp"

namespace meshstep::viewer {

namespace {

constexpr float kTimelineHeight = 122.0f;
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

Viewer::Viewer(std::unique_ptr<Session> session) : session_(std::move(session)) {
  if (const replay::LogReader* log = session_->log()) {
    angle_bound_ = std::strtod(log->parameter("min_angle", "0").c_str(), nullptr);
    history_.build(log->path());
    plots_.build(log->path(), angle_bound_);
  }
}

void Viewer::apply(const Settings& s) {
  session_->set_color_by(s.color_by);
  session_->set_theme(s.theme);
  for (std::size_t i = 0; i < scene::kLayerCount; ++i)
    session_->set_layer(static_cast<scene::Layer>(i), s.layers.has(static_cast<scene::Layer>(i)));
  session_->playback().speed = std::clamp(s.speed, Playback::kMinSpeed, Playback::kMaxSpeed);
  session_->playback().unit = s.unit;
  follow = s.follow;
  side_panel_width_ = s.side_panel_width;
  explain_open_ = s.explain_open;
  layers_open_ = s.layers_open;
  stats_open_ = s.stats_open;
  code_open_ = s.code_open;
}

void Viewer::capture(Settings& s) const {
  s.color_by = session_->options().color_by;
  s.theme = session_->options().theme;
  s.layers = session_->options().layers;
  s.speed = session_->playback().speed;
  s.unit = session_->playback().unit;
  s.follow = follow;
  s.side_panel_width = side_panel_width_;
  s.explain_open = explain_open_;
  s.layers_open = layers_open_;
  s.stats_open = stats_open_;
  s.code_open = code_open_;
}

void Viewer::cycle_color_by(int direction) {
  const int n = static_cast<int>(scene::ColorBy::count_);
  const int now = static_cast<int>(session_->options().color_by);
  session_->set_color_by(static_cast<scene::ColorBy>(((now + direction) % n + n) % n));
}

void Viewer::toggle_layer(scene::Layer layer) { session_->set_layer(layer, !session_->layer(layer)); }

void Viewer::fit_camera(int width, int height) {
  const scene::Scene& s = session_->scene();
  camera_ = scene::Camera::fit(run_box(*session_), width, height, scene::layout(s, width, height).margins);
  fit_pending_ = false;
}

// Keeps the faces the current step changed in view: pans when they leave the middle 80% of
// the canvas, and zooms out when they do not fit.
void Viewer::follow_step() {
  const scene::Scene& s = session_->scene();
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

  const float side = std::min(side_panel_width_, 0.4f * static_cast<float>(width));
  const float timeline = session_->has_timeline() ? kTimelineHeight : 0.0f;
  const float canvas_w = std::max(1.0f, static_cast<float>(width) - side);
  const float canvas_h = std::max(1.0f, static_cast<float>(height) - timeline);
  draw_canvas(0, 0, canvas_w, canvas_h);
  draw_side_panel(canvas_w, 0, side, static_cast<float>(height));
  if (session_->has_timeline()) draw_timeline(0, canvas_h, canvas_w, timeline);
  if (help_open) draw_help();
}

void Viewer::draw_canvas(float x, float y, float w, float h) {
  place(x, y, w, h);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::Begin("canvas", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                                      ImGuiWindowFlags_NoScrollWithMouse);
  const int width = static_cast<int>(w), height = static_cast<int>(h);
  canvas_rect_ = ImVec4(x, y, w, h);
  if (fit_pending_ || camera_.width() != width || camera_.height() != height) {
    if (fit_pending_ || camera_.width() <= 1) fit_camera(width, height);
    else camera_.resize(width, height);
  }
  if (follow && session_->playback().playing) follow_step();

  const scene::Scene& s = session_->scene();
  const Drawn now{session_->scene_builds(), s.visible.bits(), camera_.center().x, camera_.center().y,
                  camera_.pixels_per_unit(), width, height};
  if (!(now == drawn_)) {
    renderer_.render(s, camera_);
    drawn_ = now;
    ++canvas_renders_;
  }
  ImGui::Image(texture_id(renderer_.texture()), ImVec2(w, h));

  // Pan by dragging, zoom at the pointer with the wheel.
  const ImGuiIO& io = ImGui::GetIO();
  refresh_selection();
  if (ImGui::IsItemHovered()) {
    const ImVec2 mouse = io.MousePos;
    const Point world = camera_.to_world({mouse.x - x, mouse.y - y});
    if (io.MouseWheel != 0.0f)
      camera_.zoom_at({mouse.x - x, mouse.y - y}, std::pow(1.2, static_cast<double>(io.MouseWheel)));
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f))
      camera_.pan(io.MouseDelta.x, io.MouseDelta.y);
    // Hover: looked up again only when the pointer moves, and not in huge meshes (a scan).
    if ((io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f) && s.mesh.triangles.size() <= 200000)
      hovered_ = pick(s.mesh, world, 8.0 / camera_.pixels_per_unit());
    // A click (pressed and released without a drag) selects.
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 9.0f) select_at(world);
  } else {
    hovered_ = {};
  }
  draw_selection_overlay(x, y);
  ImGui::End();
  ImGui::PopStyleVar(2);
}

void Viewer::draw_help() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.94f);
  ImGui::Begin("Keys (? or F1 to close)", &help_open,
               ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
  // Two pairs of columns (key, what it does), filled row by row.
  if (ImGui::BeginTable("keys", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const KeyAction& a : key_actions()) {
      if (!a.what) continue;  // one line stands for a family (bookmarks 1-9)
      ImGui::TableNextColumn();
      const bool digit = a.chord.key >= '1' && a.chord.key <= '9';
      ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", digit ? (a.chord.ctrl ? "Ctrl+1..9" : "1..9") : a.keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(a.what);
    }
    ImGui::EndTable();
  }
  ImGui::TextUnformatted("Drag the canvas to pan, turn the wheel to zoom at the pointer; drag the timeline to scrub.");
  ImGui::End();
}

scene::Image Viewer::canvas_picture() {
  renderer_.render(session_->scene(), camera_);
  drawn_ = Drawn{};
  return renderer_.read_pixels();
}

}  // namespace meshstep::viewer
