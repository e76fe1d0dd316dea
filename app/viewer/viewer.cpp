#include "viewer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "imgui_gl.hpp"
#include "keys.hpp"
#include "meshstep/refine/quality.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/scene/svg.hpp"
#include "timeline.hpp"

namespace meshstep::viewer {

namespace {

constexpr float kTimelineHeight = 122.0f;
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoBringToFrontOnFocus;

void place(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
}

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

std::vector<std::uint64_t> Viewer::selected_vertex_steps() const {
  std::vector<std::uint64_t> steps;
  const replay::LogReader* log = session_->log();
  if (!log || selected_.kind != Picked::Kind::vertex) return steps;
  for (const std::uint32_t e : history_.events_of_vertex(selected_.index)) {
    const std::uint64_t k = log->step_of_event(e);
    if (k < log->step_count() && (steps.empty() || steps.back() != k + 1)) steps.push_back(k + 1);
  }
  return steps;
}
Viewer::~Viewer() = default;

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

void Viewer::select_at(Point world) {
  const scene::Scene& s = session_->scene();
  selected_ = pick(s.mesh, world, 8.0 / camera_.pixels_per_unit());
  lepp_ = {};
  if (selected_.kind == Picked::Kind::triangle) {
    selected_vertices_ = s.mesh.triangles[selected_.index];
    lepp_ = lepp_path(s.mesh, selected_.index);
  }
  selection_build_ = session_->scene_builds();
}

// After the scene changed: the selected triangle is looked for by its vertices (gone: the
// selection goes); a vertex keeps its id, which the log gives it for the whole run.
void Viewer::refresh_selection() {
  if (selected_.kind == Picked::Kind::none || selection_build_ == session_->scene_builds()) return;
  const scene::Scene& s = session_->scene();
  selection_build_ = session_->scene_builds();
  hovered_ = {};
  if (selected_.kind == Picked::Kind::vertex) return;
  auto sorted = selected_vertices_;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t t = 0; t < s.mesh.triangles.size(); ++t) {
    auto v = s.mesh.triangles[t];
    std::sort(v.begin(), v.end());
    if (v == sorted) {
      selected_.index = t;
      lepp_ = lepp_path(s.mesh, t);
      return;
    }
  }
  selected_ = {};
  lepp_ = {};
}

// The hovered and selected elements over the canvas picture, drawn by ImGui (they change
// with the pointer; the renderer's picture stays as it is).
void Viewer::draw_selection_overlay(float x, float y) {
  const scene::Scene& s = session_->scene();
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  const auto screen = [&](std::uint32_t v) {
    const Point p = camera_.to_screen(s.mesh.points[v]);
    return ImVec2(static_cast<float>(p.x) + x, static_cast<float>(p.y) + y);
  };
  const auto outline = [&](std::uint32_t t, ImU32 colour, float width) {
    if (t >= s.mesh.triangles.size()) return;
    const auto& v = s.mesh.triangles[t];
    draw.AddTriangle(screen(v[0]), screen(v[1]), screen(v[2]), colour, width);
  };
  const auto centroid = [&](std::uint32_t t) {
    const auto& v = s.mesh.triangles[t];
    const ImVec2 a = screen(v[0]), b = screen(v[1]), c = screen(v[2]);
    return ImVec2((a.x + b.x + c.x) / 3.0f, (a.y + b.y + c.y) / 3.0f);
  };
  if (hovered_.kind == Picked::Kind::triangle && !(hovered_ == selected_)) outline(hovered_.index, IM_COL32(0, 114, 178, 200), 2.0f);
  if (hovered_.kind == Picked::Kind::vertex) draw.AddCircle(screen(hovered_.index), 7.0f, IM_COL32(0, 114, 178, 220), 0, 2.0f);
  if (selected_.kind == Picked::Kind::triangle) {
    // Its Lepp path: a line through the centroids in order, the terminal edge thick.
    for (std::size_t i = 0; i + 1 < lepp_.triangles.size(); ++i)
      draw.AddLine(centroid(lepp_.triangles[i]), centroid(lepp_.triangles[i + 1]), IM_COL32(204, 121, 167, 255), 2.5f);
    for (const std::uint32_t t : lepp_.triangles) draw.AddCircleFilled(centroid(t), 3.5f, IM_COL32(204, 121, 167, 255));
    if (!lepp_.triangles.empty()) draw.AddLine(screen(lepp_.a), screen(lepp_.b), IM_COL32(204, 121, 167, 255), 5.0f);
    outline(selected_.index, IM_COL32(213, 94, 0, 255), 3.0f);
  }
  if (selected_.kind == Picked::Kind::vertex && selected_.index < s.mesh.points.size())
    draw.AddCircle(screen(selected_.index), 9.0f, IM_COL32(213, 94, 0, 255), 0, 3.0f);
}

std::string Viewer::selection_text() {
  const scene::Scene& s = session_->scene();
  char buf[256];
  if (selected_.kind == Picked::Kind::triangle) {
    const TriangleFacts f = triangle_facts(s.mesh, selected_.index);
    std::snprintf(buf, sizeof buf, "triangle %u %u %u: angles %.1f %.1f %.1f, area %.4g", f.vertices[0], f.vertices[1],
                  f.vertices[2], f.angles[0], f.angles[1], f.angles[2], f.area);
    std::string out = buf;
    if (angle_bound_ > 0) {
      std::snprintf(buf, sizeof buf, ", smallest angle %.1f %s %.4g (the bound)", f.min_angle,
                    f.min_angle < angle_bound_ ? "<" : ">=", angle_bound_);
      out += buf;
    }
    std::snprintf(buf, sizeof buf, "; Lepp path of %zu to edge %u-%u%s", lepp_.triangles.size(), lepp_.a, lepp_.b,
                  lepp_.boundary ? " (on the boundary)" : "");
    return out + buf;
  }
  if (selected_.kind == Picked::Kind::vertex) {
    const std::uint32_t v = selected_.index;
    const Point& p = s.mesh.points[v];
    std::snprintf(buf, sizeof buf, "vertex %u at (%.6g, %.6g)", v, p.x, p.y);
    std::string out = buf;
    const replay::LogReader* log = session_->log();
    if (!log || v >= log->vertices().size()) return out + (log ? "" : ", of the mesh");
    const replay::VertexInfo& info = log->vertices()[v];
    const std::uint64_t inputs = std::strtoull(log->parameter("input_vertices", "0").c_str(), nullptr, 10);
    const std::uint64_t step = log->step_of_event(info.event);
    if (info.input_index < inputs) {
      out += ": input vertex " + std::to_string(info.input_index + 1);
    } else {
      out += ": Steiner";
    }
    if (step < log->step_count()) {
      std::string kind = replay::name(log->step_kind(step));
      std::replace(kind.begin(), kind.end(), '_', ' ');
      out += ", inserted by step " + std::to_string(step + 1) + " (" + kind + ")";
    }
    return out;
  }
  return "";
}

// What is selected, in words, with a jump to the step that made a vertex.
void Viewer::draw_selection_panel() {
  if (selected_.kind == Picked::Kind::none) return;
  if (!ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (selection_text_of_ != std::pair{selected_, session_->scene_builds()}) {
    selection_text_ = selection_text();
    selection_text_of_ = {selected_, session_->scene_builds()};
  }
  ImGui::TextWrapped("%s", selection_text_.c_str());
  const replay::LogReader* log = session_->log();
  if (selected_.kind == Picked::Kind::vertex && log && selected_.index < log->vertices().size()) {
    const std::uint64_t step = log->step_of_event(log->vertices()[selected_.index].event);
    if (step < log->step_count() && ImGui::Button("Go to the step that inserted it")) session_->seek_step(step + 1);
    // Its history: the steps that inserted it, flipped or split its edges, removed it.
    if (!history_.ready()) {
      ImGui::TextDisabled("indexing the run's history...");
    } else {
      if (history_steps_of_ != std::pair{selected_, std::size_t{0}}) {
        history_steps_ = selected_vertex_steps();
        history_steps_of_ = {selected_, 0};
      }
      ImGui::Text("history: %zu steps (ticks on the timeline)", history_steps_.size());
      constexpr std::size_t kShown = 16;
      for (std::size_t i = 0; i < std::min(history_steps_.size(), kShown); ++i) {
        char label[32];
        std::snprintf(label, sizeof label, "%llu", static_cast<unsigned long long>(history_steps_[i]));
        if (i % 8) ImGui::SameLine();
        if (ImGui::SmallButton(label)) session_->seek_step(history_steps_[i]);
      }
      if (history_steps_.size() > kShown) ImGui::TextDisabled("and %zu more", history_steps_.size() - kShown);
    }
  }
  if (ImGui::Button("Clear the selection")) selected_ = {};
}

// The whole run at a glance: triangles, smallest angle and bad triangles after each step,
// the cursor's step marked on each.
void Viewer::draw_run_plots(float width) {
  const replay::LogReader* log = session_->log();
  if (!log) return;
  ImGui::Separator();
  if (!plots_.ready()) {
    ImGui::TextDisabled("plotting the whole run...");
    return;
  }
  if (!plots_.error().empty() || plots_.triangles().empty()) return;
  const std::array<const std::vector<float>*, 3> series = {&plots_.triangles(), &plots_.smallest_angle(), &plots_.bad()};
  if (!plot_scales_known_) {
    for (std::size_t i = 0; i < 3; ++i) {
      float lo = FLT_MAX, hi = -FLT_MAX;
      for (const float v : *series[i])
        if (!std::isnan(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      plot_scales_[2 * i] = lo == FLT_MAX ? 0.0f : std::min(lo, 0.0f);
      plot_scales_[2 * i + 1] = hi == -FLT_MAX ? 1.0f : std::max(hi, 1.0f);
    }
    plot_scales_known_ = true;
  }
  static constexpr const char* kTitles[] = {"triangles", "smallest angle", "bad triangles left"};
  const std::uint64_t step = session_->cursor_info().step;
  for (std::size_t i = 0; i < 3; ++i) {
    if (i == 2 && angle_bound_ <= 0.0) break;
    const std::vector<float>& v = *series[i];
    const std::size_t at = std::min<std::size_t>(step, v.size() - 1);
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s: %.6g", kTitles[i], static_cast<double>(v[at]));
    ImGui::PushID(static_cast<int>(i));
    ImGui::PlotLines("##plot", v.data(), static_cast<int>(v.size()), 0, overlay, plot_scales_[2 * i],
                     plot_scales_[2 * i + 1], ImVec2(width, 48.0f));
    ImGui::PopID();
    const ImVec2 lo = ImGui::GetItemRectMin();
    const float plot_w = width;
    const float x = lo.x + plot_w * static_cast<float>(at) / static_cast<float>(std::max<std::size_t>(1, v.size() - 1));
    ImGui::GetWindowDrawList()->AddLine(ImVec2(x, lo.y), ImVec2(x, lo.y + 48.0f), IM_COL32(255, 60, 60, 255), 1.5f);
  }
}

const Stats& Viewer::stats() {
  const scene::Scene& s = session_->scene();
  if (stats_of_build_ == session_->scene_builds()) return stats_;
  stats_ = Stats{};
  std::vector<bool> used(s.mesh.points.size(), false);
  stats_.min_angle = 180.0;
  for (const auto& t : s.mesh.triangles) {
    if (t[0] >= used.size() || t[1] >= used.size() || t[2] >= used.size()) continue;
    const auto q = quality::shape(s.mesh.points[t[0]], s.mesh.points[t[1]], s.mesh.points[t[2]]);
    const double smallest = q.min_angle_deg();
    stats_.min_angle = std::min(stats_.min_angle, smallest);
    stats_.max_angle = std::max(stats_.max_angle, q.max_angle_deg());
    const auto bin = static_cast<std::size_t>(std::clamp(smallest / 60.0 * 18.0, 0.0, 17.0));
    stats_.histogram[bin] += 1.0f;
    for (const std::uint32_t v : t) used[v] = true;
  }
  stats_.triangles = s.mesh.triangles.size();
  // A log numbers the input's vertices first (its input_vertices parameter counts them);
  // a mesh file lists them first too (input_vertex_count is not known here: all count).
  const replay::LogReader* log = session_->log();
  const std::uint64_t inputs =
      log ? std::strtoull(log->parameter("input_vertices", "0").c_str(), nullptr, 10) : used.size();
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) continue;
    ++stats_.vertices;
    if (log && v < log->vertices().size()) stats_.steiner += log->vertices()[v].input_index >= inputs;
  }
  if (stats_.triangles == 0) stats_.min_angle = 0.0;
  stats_of_build_ = session_->scene_builds();
  return stats_;
}

void Viewer::draw_side_panel(float x, float y, float w, float h) {
  place(x, y, w, h);
  ImGui::Begin("meshstep", nullptr, kPanelFlags);
  // The file's name: its folder is in the window's title.
  const std::string& title = session_->title();
  const std::size_t slash = title.rfind('/');
  ImGui::TextWrapped("%s", title.c_str() + (slash == std::string::npos ? 0 : slash + 1));
  ImGui::Separator();

  draw_selection_panel();
  ImGui::SetNextItemOpen(explain_open_);
  if ((explain_open_ = ImGui::CollapsingHeader("Why this step?"))) {
    const scene::Explanation& e = session_->explanation();
    ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", e.heading.c_str());
    for (const std::string& line : e.lines) ImGui::TextWrapped("%s", line.c_str());
  }

  draw_pseudocode();

  draw_invariants();
  draw_export();

  ImGui::SetNextItemOpen(layers_open_);
  if ((layers_open_ = ImGui::CollapsingHeader("Layers and colours"))) {
    int color = static_cast<int>(session_->options().color_by);
    static const char* const kColorNames[] = {"none", "smallest angle", "quality (vs bound)", "area", "region", "age"};
    if (ImGui::Combo("colour by (C)", &color, kColorNames, IM_ARRAYSIZE(kColorNames)))
      session_->set_color_by(static_cast<scene::ColorBy>(color));
    bool dark = session_->options().theme == scene::Theme::dark;
    if (ImGui::Checkbox("dark theme (T)", &dark)) session_->set_theme(dark ? scene::Theme::dark : scene::Theme::light);
    ImGui::SameLine();
    ImGui::Checkbox("follow (L)", &follow);
    for (std::size_t i = 0; i < scene::kLayerCount; ++i) {
      const auto layer = static_cast<scene::Layer>(i);
      bool on = session_->layer(layer);
      if (i % 3 != 0) ImGui::SameLine(static_cast<float>(i % 3) * (w - 16.0f) / 3.0f + 8.0f);
      if (ImGui::Checkbox(scene::name(layer), &on)) session_->set_layer(layer, on);
    }
  }

  ImGui::SetNextItemOpen(stats_open_);
  if ((stats_open_ = ImGui::CollapsingHeader("Statistics at the cursor"))) {
    const Stats& st = stats();
    ImGui::Text("%zu vertices (%zu Steiner), %zu triangles", st.vertices, st.steiner, st.triangles);
    ImGui::Text("angles from %.2f%s to %.2f%s", st.min_angle, "\u00B0", st.max_angle, "\u00B0");
    ImGui::PlotHistogram("##angles", st.histogram.data(), static_cast<int>(st.histogram.size()), 0,
                         "smallest angle per triangle, 0-60\u00B0", 0.0f, FLT_MAX, ImVec2(w - 24.0f, 70.0f));
    // The run's angle bound, as a line across the histogram: bars left of it are the bad.
    const double bound = angle_bound_;
    if (bound > 0.0 && bound < 60.0) {
      const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
      const float x = lo.x + static_cast<float>(bound / 60.0) * (hi.x - lo.x);
      ImGui::GetWindowDrawList()->AddLine(ImVec2(x, lo.y), ImVec2(x, hi.y), IM_COL32(213, 94, 0, 255), 2.0f);
      ImGui::Text("bound %.4g\u00B0 (the orange line)", bound);
    }
    draw_run_plots(w - 24.0f);
  }
  ImGui::End();
}

// The running algorithm's pseudo-code, the line of the cursor's event highlighted.
void Viewer::draw_pseudocode() {
  const replay::LogReader* log = session_->log();
  if (!log) return;
  ImGui::SetNextItemOpen(code_open_);
  if (!(code_open_ = ImGui::CollapsingHeader("Pseudo-code"))) return;
  const std::uint64_t at = session_->cursor_info().position;
  if (at != code_position_) {
    code_ = pseudocode_at(*log, *session_->cursor());
    code_position_ = at;
  }
  if (!code_.code) return;
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", code_.code->title.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.6f, 0.6f, 0.6f, 1.0f));
  ImGui::TextWrapped("%s", code_.code->reference.c_str());
  ImGui::PopStyleColor();
  // Lines wrap at the panel's edge, their continuation indented under their text; the
  // current lines get a band behind them, as a debugger marks the line it stopped at (drawn
  // on a channel below the text, once the wrapped text's height is known).
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  draw.ChannelsSplit(2);
  const auto& lines = code_.code->lines;
  const float right = ImGui::GetCursorPosX() + ImGui::GetContentRegionAvail().x;
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    const std::string& line = lines[static_cast<std::size_t>(i)];
    const std::size_t indent = line.find_first_not_of(' ');
    const float shift = ImGui::CalcTextSize(" ").x * static_cast<float>(indent == std::string::npos ? 0 : indent);
    draw.ChannelsSetCurrent(1);
    ImGui::Indent(shift + 1.0f);
    ImGui::PushTextWrapPos(right);
    ImGui::TextUnformatted(line.c_str() + (indent == std::string::npos ? line.size() : indent));
    ImGui::PopTextWrapPos();
    ImGui::Unindent(shift + 1.0f);
    const bool current = code_.line >= 0 && i >= code_.line && i < code_.line + std::max(1, code_.lines);
    if (current) {
      draw.ChannelsSetCurrent(0);
      const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
      draw.AddRectFilled(ImVec2(ImGui::GetWindowPos().x + 4.0f, lo.y), ImVec2(ImGui::GetWindowPos().x + right, hi.y),
                         IM_COL32(230, 159, 0, 110));
    }
  }
  draw.ChannelsMerge();
}

// Pictures of the moment (canvas as PNG or SVG, the whole window) and a video of a range of
// steps, written beside the log.
void Viewer::draw_export() {
  if (!ImGui::CollapsingHeader("Export")) return;
  const replay::LogReader* log = session_->log();
  const std::string base = log ? log->path() : session_->title();
  const auto step = static_cast<unsigned long long>(session_->cursor_info().step);
  if (ImGui::Button("canvas PNG")) {
    const std::string file = export_name(base, step, "step", ".png");
    try {
      scene::write_png(file, canvas_picture(), 6);
      export_status = "wrote " + file;
    } catch (const std::exception& e) {
      export_status = std::string("failed: ") + e.what();
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("canvas SVG")) {
    const std::string file = export_name(base, step, "step", ".svg");
    try {
      io::write_file_atomically(file, scene::to_svg(session_->scene(), camera_));
      export_status = "wrote " + file;
    } catch (const std::exception& e) {
      export_status = std::string("failed: ") + e.what();
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("window PNG")) {
    window_capture_path = export_name(base, step, "window_step", ".png");
    export_status = "wrote " + window_capture_path;
  }
  if (log && log->step_count() > 0) {
    const int last = static_cast<int>(log->step_count());
    if (export_range_[1] == 0) export_range_[1] = last;
    ImGui::SetNextItemWidth(160);
    ImGui::DragInt2("steps##range", export_range_, 1.0f, 0, last);
    ImGui::SameLine();
    if (export_job_.running()) {
      ImGui::TextDisabled("writing...");
    } else if (ImGui::Button("video MP4")) {
      const int from = std::clamp(std::min(export_range_[0], export_range_[1]), 0, last);
      const int to = std::clamp(std::max(export_range_[0], export_range_[1]), 0, last);
      const std::string file = export_name(base, static_cast<unsigned long long>(from), "steps_", "") + "-" +
                               std::to_string(to) + ".mp4";
      export_job_.start(log->path(), file, static_cast<unsigned long long>(from), static_cast<unsigned long long>(to));
    }
    if (!export_job_.status().empty()) ImGui::TextWrapped("%s", export_job_.status().c_str());
  }
  if (!export_status.empty()) ImGui::TextWrapped("%s", export_status.c_str());
}

// "Check every step": the mesh valid and Delaunay at every step boundary, in the background;
// a break takes you to the step that made it.
void Viewer::draw_invariants() {
  const replay::LogReader* log = session_->log();
  if (!log || !ImGui::CollapsingHeader("Invariants")) return;
  if (invariants_.running()) {
    ImGui::ProgressBar(static_cast<float>(std::min<double>(
                           1.0, static_cast<double>(invariants_.checked()) /
                                    static_cast<double>(std::max<std::uint64_t>(1, log->step_count() + 1)))),
                       ImVec2(-1, 0), "checking...");
    return;
  }
  if (ImGui::Button("Check every step: valid, Delaunay")) {
    invariants_text_.clear();
    invariants_.start(log->path());
    return;
  }
  if (const auto& report = invariants_.report()) {
    if (invariants_text_.empty()) invariants_text_ = describe(*report);
    ImGui::TextWrapped("%s", invariants_text_.c_str());
    if (!report->ok && ImGui::Button("Go to the step that breaks it")) session_->seek_step(report->boundary);
  } else if (!invariants_.error().empty()) {
    ImGui::TextWrapped("%s", invariants_.error().c_str());
  }
}

void Viewer::draw_transport() {
  Session& s = *session_;
  const CursorInfo c = s.cursor_info();
  if (ImGui::Button("|<")) s.to_start();
  ImGui::SameLine();
  if (ImGui::Button("<<")) s.move(Unit::phase, -1);
  ImGui::SameLine();
  if (ImGui::Button("<")) s.move(Unit::step, -1);
  ImGui::SameLine();
  if (ImGui::Button(s.playback().playing ? "pause" : "play", ImVec2(56, 0))) s.toggle_play();
  ImGui::SameLine();
  if (ImGui::Button(">")) s.move(Unit::step, +1);
  ImGui::SameLine();
  if (ImGui::Button(">>")) s.move(Unit::phase, +1);
  ImGui::SameLine();
  if (ImGui::Button(">|")) s.to_end();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(150);
  float speed = static_cast<float>(s.playback().speed);
  if (ImGui::SliderFloat("##speed", &speed, static_cast<float>(Playback::kMinSpeed),
                         static_cast<float>(Playback::kMaxSpeed), "%.2f /s", ImGuiSliderFlags_Logarithmic))
    s.playback().speed = speed;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  int unit = static_cast<int>(s.playback().unit);
  static const char* const kUnits[] = {"events", "steps", "phases"};
  if (ImGui::Combo("##unit", &unit, kUnits, 3)) s.playback().unit = static_cast<Unit>(unit);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  if (ImGui::InputTextWithHint("##goto", "go to step", goto_text_, sizeof goto_text_,
                               ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CharsDecimal)) {
    s.seek_step(std::strtoull(goto_text_, nullptr, 10));
    goto_text_[0] = '\0';
  }
  (void)c;  // the bar itself says where the cursor is (timeline.cpp)
}

void Viewer::draw_timeline(float x, float y, float w, float h) {
  place(x, y, w, h);
  ImGui::Begin("timeline", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  draw_transport();
  draw_timeline_bar(ImGui::GetContentRegionAvail().y - 4.0f);
  ImGui::End();
}

void Viewer::draw_timeline_bar(float height) {
  const replay::LogReader& log = *session_->log();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  if (width < 8.0f || height < 8.0f) return;
  ImGui::InvisibleButton("##timeline", ImVec2(width, height));
  const std::uint64_t events = std::max<std::uint64_t>(1, log.event_count());
  if (ImGui::IsItemActive()) {
    const double t = std::clamp((ImGui::GetIO().MousePos.x - origin.x) / width, 0.0f, 1.0f);
    session_->seek(static_cast<std::uint64_t>(std::llround(t * static_cast<double>(events))));
  }
  draw_timeline_picture(*ImGui::GetWindowDrawList(), log, timeline_cache_, *session_, origin, ImVec2(width, height));
  // The selected vertex's history as ticks along the bar's bottom.
  if (selected_.kind == Picked::Kind::vertex) {
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    const float bottom = origin.y + height;
    for (const std::uint32_t e : history_.events_of_vertex(selected_.index)) {
      const float x = origin.x + static_cast<float>(static_cast<double>(e) / static_cast<double>(events)) * width;
      draw.AddLine(ImVec2(x, bottom - 16.0f), ImVec2(x, bottom), IM_COL32(204, 121, 167, 255), 2.0f);
    }
  }
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
