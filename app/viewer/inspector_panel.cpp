// The viewer's inspector: what the pointer is over, what a click selected (a triangle with
// its Lepp path, a vertex with its history), drawn over the canvas and said in the panel.
#include <algorithm>
#include <cstdio>

#include "viewer.hpp"

namespace meshstep::viewer {

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

}  // namespace meshstep::viewer
