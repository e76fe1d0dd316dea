// The viewer's inspector: what the pointer is over, what a click selected (a vertex, a
// segment, a triangle with its Lepp path), drawn over the canvas, and its history (from the
// element index) as buttons in the panel. The words are in selection_words.cpp.
#include <algorithm>
#include <cstdio>

#include "compare_view.hpp"  // complete, for ~Viewer
#include "viewer.hpp"

namespace meshstep::viewer {

Viewer::~Viewer() = default;

// Made again only when the selection, the canvas's moment or the index's readiness changes
// (an idle frame compares three values).
const SelectionStory& Viewer::selection_story() {
  const replay::LogReader* log = session_->log();
  const std::tuple<Picked, std::uint64_t, bool> of{selected_, log ? session_->shown_position() : 0, history_.ready()};
  if (of != story_of_) {
    story_ = log ? viewer::selection_story(*log, history_, selected_, selected_vertices_, std::get<1>(of))
                 : SelectionStory{};
    story_of_ = of;
    selection_text_of_ = {{}, SIZE_MAX};  // the words tell the story too
  }
  return story_;
}

void Viewer::select_at(Point world) {
  const scene::Scene& s = session_->scene();
  // The pick's tolerance is a few pixels of the canvas as it will be drawn: a pending fit is
  // done first, and before the first frame (a script's select) no pixel has a size yet,
  // so only an exact hit picks a vertex or a segment.
  const bool canvas_known = camera_.width() > 1;
  if (fit_pending_ && canvas_known) fit_camera(camera_.width(), camera_.height());
  const double pixel = canvas_known ? 1.0 / camera_.pixels_per_unit() : 0.0;
  // World points are the plane's, in 3D too: the camera's pixels are about the same size.
  select(pick(s.mesh, constrained_edges(s), world, 8.0 * pixel, 5.0 * pixel));
}

void Viewer::select(const Picked& picked) {
  const scene::Scene& s = session_->scene();
  selected_ = picked;
  lepp_ = {};
  if (selected_.kind == Picked::Kind::triangle) {
    selected_vertices_ = s.mesh.triangles[selected_.index];
    lepp_ = lepp_path(s.mesh, selected_.index, view3d_.heights());
  }
  selection_build_ = session_->scene_builds();
}

// What is under a pixel of the canvas, named as the inspector names it: a triangle of the
// session's (planar) scene, a vertex by its id, a segment by its ends. In 3D, the front
// triangle on the picture or a vertex of it (no segments: a terrain has none).
void Viewer::pick_under(Point screen, Picked& picked) {
  const scene::Scene& s = session_->scene();
  const Point at = camera_.to_world(screen);
  const double pixel = 1.0 / camera_.pixels_per_unit();
  if (!view3d_.on()) {
    if (hover_edges_build_ != session_->scene_builds()) {  // the segments, found once per scene
      hover_edges_ = constrained_edges(s);
      hover_edges_build_ = session_->scene_builds();
    }
    picked = pick(s.mesh, hover_edges_, at, 8.0 * pixel, 5.0 * pixel);
    return;
  }
  // Before the worker's first 3D picture, the canvas still shows the planar one.
  if (worker_ && !picture_in_3d_) {
    picked = {};
    return;
  }
  const scene::Scene& shown = shown_scene();
  picked = pick_front(shown.mesh, at, 8.0 * pixel);
  if (picked.kind == Picked::Kind::triangle) {
    // Lifted triangles are in drawing order: the planar one has the same three vertices.
    const std::uint32_t t = find_triangle(s.mesh, shown.mesh.triangles[picked.index]);
    picked = t == kNoIndex ? Picked{} : Picked{Picked::Kind::triangle, t};
  }
}

// After the scene changed: the selected triangle is looked for by its vertices (gone: the
// selection goes); a vertex keeps its id, which the log gives it for the whole run, and a
// segment its piece's ends (its input segment is the same at every moment).
void Viewer::refresh_selection() {
  if (selected_.kind == Picked::Kind::none || selection_build_ == session_->scene_builds()) return;
  const scene::Scene& s = session_->scene();
  selection_build_ = session_->scene_builds();
  hovered_ = {};
  if (selected_.kind != Picked::Kind::triangle) return;
  if (const std::uint32_t t = find_triangle(s.mesh, selected_vertices_); t != kNoIndex) {
    selected_.index = t;
    lepp_ = lepp_path(s.mesh, t, view3d_.heights());
    return;
  }
  selected_ = {};
  lepp_ = {};
}

// The hovered and selected elements over the canvas picture, drawn by ImGui (they change
// with the pointer; the renderer's picture stays as it is).
void Viewer::draw_selection_overlay(float x, float y) {
  const scene::Scene& s = session_->scene();
  // Where the vertices are in the picture: the shown scene's points (in 3D the lifted ones,
  // index for index the planar scene's). Nothing while the worker's picture is of the other
  // view (just after a switch).
  if (worker_ && view3d_.on() != picture_in_3d_) return;
  const std::vector<Point>& points = shown_scene().mesh.points;
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  const auto screen = [&](std::uint32_t v) {
    const Point p = camera_.to_screen(points[v]);
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
  const ImU32 selected_colour = IM_COL32(213, 94, 0, 255);
  if (hovered_.kind == Picked::Kind::triangle && !(hovered_ == selected_)) outline(hovered_.index, IM_COL32(0, 114, 178, 200), 2.0f);
  if (hovered_.kind == Picked::Kind::vertex) draw.AddCircle(screen(hovered_.index), 7.0f, IM_COL32(0, 114, 178, 220), 0, 2.0f);
  if (selected_.kind == Picked::Kind::triangle) {
    // Its Lepp path: a line through the centroids in order, the terminal edge thick.
    for (std::size_t i = 0; i + 1 < lepp_.triangles.size(); ++i)
      draw.AddLine(centroid(lepp_.triangles[i]), centroid(lepp_.triangles[i + 1]), IM_COL32(204, 121, 167, 255), 2.5f);
    for (const std::uint32_t t : lepp_.triangles) draw.AddCircleFilled(centroid(t), 3.5f, IM_COL32(204, 121, 167, 255));
    if (!lepp_.triangles.empty()) draw.AddLine(screen(lepp_.a), screen(lepp_.b), IM_COL32(204, 121, 167, 255), 5.0f);
    outline(selected_.index, selected_colour, 3.0f);
  }
  if (selected_.kind == Picked::Kind::vertex && selected_.index < s.mesh.points.size())
    draw.AddCircle(screen(selected_.index), 9.0f, selected_colour, 0, 3.0f);
  if (selected_.kind == Picked::Kind::segment) {
    // The input segment's pieces at this moment, their ends ringed; the clicked piece alone
    // until the index knows the segment.
    const SegmentStory& story = selection_story().segment;
    const auto piece = [&](VertexId a, VertexId b) {
      if (a >= s.mesh.points.size() || b >= s.mesh.points.size()) return;
      draw.AddLine(screen(a), screen(b), selected_colour, 4.0f);
      draw.AddCircle(screen(a), 5.0f, selected_colour, 0, 2.0f);
      draw.AddCircle(screen(b), 5.0f, selected_colour, 0, 2.0f);
    };
    if (story.segment == kNone) piece(selected_.index, selected_.other);
    for (const auto& [a, b] : story.pieces) piece(a, b);
  }
}

namespace {

// A row of buttons, one a step, that move the cursor there.
void step_buttons(const std::vector<std::uint64_t>& steps, Session& session) {
  constexpr std::size_t kShown = 16;
  for (std::size_t i = 0; i < std::min(steps.size(), kShown); ++i) {
    char label[32];
    std::snprintf(label, sizeof label, "%llu", static_cast<unsigned long long>(steps[i]));
    if (i % 8) ImGui::SameLine();
    if (ImGui::SmallButton(label)) session.seek_step(steps[i]);
  }
  if (steps.size() > kShown) ImGui::TextDisabled("and %zu more", steps.size() - kShown);
}

// A button to the end of the step of event e (1-based steps, as the caption counts).
void event_button(const char* what, std::uint64_t e, Session& session) {
  const replay::LogReader& log = *session.log();
  if (e == kNoEvent || e >= log.event_count()) return;
  const std::uint64_t step = log.step_of_event(e);
  if (step >= log.step_count()) return;
  char label[96];
  std::snprintf(label, sizeof label, "Go to the step that %s it (%llu)", what, static_cast<unsigned long long>(step + 1));
  if (ImGui::Button(label)) session.seek_step(step + 1);
}

}  // namespace

// What is selected, in words, with jumps to the steps of its history.
void Viewer::draw_selection_panel() {
  if (selected_.kind == Picked::Kind::none) return;
  if (!ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const SelectionStory& story = selection_story();
  if (selection_text_of_ != std::pair{selected_, session_->scene_builds()}) {
    selection_text_ = selection_text();
    selection_text_of_ = {selected_, session_->scene_builds()};
  }
  ImGui::TextWrapped("%s", selection_text_.c_str());
  const replay::LogReader* log = session_->log();
  if (log && selected_.kind == Picked::Kind::vertex && selected_.index < log->vertices().size())
    event_button("inserted", log->vertices()[selected_.index].event, *session_);
  if (log && selected_.kind == Picked::Kind::triangle) {
    event_button("made", story.triangle.created, *session_);
    event_button("replaced", story.triangle.removed, *session_);
  }
  if (log) {
    // Its history: a vertex's insertion, the flips and splits of its edges, the cavities on
    // it, its removal; a triangle's making, flags and replacement; a segment's constraint and
    // splits.
    if (!history_.ready()) {
      ImGui::TextDisabled("indexing the run's history...");
    } else {
      const std::size_t n = story.steps.size();
      ImGui::Text("history: %zu step%s (ticks on the timeline)", n, n == 1 ? "" : "s");
      step_buttons(story.steps, *session_);
    }
  }
  if (ImGui::Button("Clear the selection")) selected_ = {};
}

}  // namespace meshstep::viewer
