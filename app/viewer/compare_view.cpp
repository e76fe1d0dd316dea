#include "compare_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "imgui_gl.hpp"
#include "meshstep/error.hpp"
#include "meshstep/scene/layout.hpp"
#include "panel_style.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

namespace {

// The gap between canvases, and the line over each for its run's description.
constexpr float kGap = 4.0f;
// The difference overlay's colour: Okabe-Ito's reddish purple, apart from every colouring's
// ramp and from the highlights, and thick enough to be seen over a dense mesh.
constexpr ImU32 kDifferenceColor = IM_COL32(204, 121, 167, 255);
constexpr float kDifferenceWidth = 2.5f;

// Every vertex a run ever has: a camera fitted to the runs' boxes holds still as they grow.
BBox log_box(const replay::LogReader& log) {
  BBox box;
  for (const replay::VertexInfo& v : log.vertices())
    if (v.event != kNone) box.add(v.point);
  return box;
}

// A few values in order (std::sort on these small arrays trips GCC 12's -Warray-bounds).
template <class T, std::size_t N>
void sort_first(std::array<T, N>& a, std::size_t n) {
  for (std::size_t i = 1; i < n; ++i)
    for (std::size_t j = i; j > 0 && a[j] < a[j - 1]; --j) std::swap(a[j], a[j - 1]);
}

// Fills `outer` but for the `holes` (disjoint rectangles inside it, as x, y, w, h): the
// canvas window's background where no picture covers it. Drawn whole under the pictures, it
// cost llvmpipe a blended pass over the whole canvas area every frame (half the UI's pixels
// with four runs) for pixels the opaque pictures then overwrote.
void fill_around(ImDrawList& draw, const ImVec4& outer, const ImVec4* holes, std::size_t count, ImU32 color) {
  // Horizontal bands between the holes' top and bottom edges; in each, the spans no hole
  // crosses.
  std::array<float, 2 * kMaxRunsSideBySide + 2> ys{};
  std::size_t n = 0;
  ys[n++] = outer.y;
  ys[n++] = outer.y + outer.w;
  for (std::size_t i = 0; i < count; ++i) ys[n++] = holes[i].y, ys[n++] = holes[i].y + holes[i].w;
  sort_first(ys, n);
  for (std::size_t b = 0; b + 1 < n; ++b) {
    const float y0 = std::max(ys[b], outer.y), y1 = std::min(ys[b + 1], outer.y + outer.w);
    if (y1 <= y0) continue;
    std::array<std::array<float, 2>, kMaxRunsSideBySide> spans{};
    std::size_t m = 0;
    for (std::size_t i = 0; i < count; ++i)
      if (holes[i].y <= y0 && holes[i].y + holes[i].w >= y1) spans[m++] = {holes[i].x, holes[i].x + holes[i].z};
    sort_first(spans, m);
    float x = outer.x;
    for (std::size_t i = 0; i < m; ++i) {
      if (spans[i][0] > x) draw.AddRectFilled(ImVec2(x, y0), ImVec2(spans[i][0], y1), color);
      x = std::max(x, spans[i][1]);
    }
    if (outer.x + outer.z > x) draw.AddRectFilled(ImVec2(x, y0), ImVec2(outer.x + outer.z, y1), color);
  }
}

}  // namespace

// The workers' readers together keep no more writes decoded than one reader of a log of
// half LogReader's budget would: with four 1e5-point triangulations (logs of 11 MB) kept
// whole, the viewer held about 100 MiB more (docs/viewer.md). Logs over their share are
// read from their blocks, about 9 times slower to seek, which the workers absorb.
std::uint64_t keep_writes_bytes(std::size_t runs) {
  return replay::LogReader::kKeepWritesBytes / (2 * std::max<std::size_t>(1, runs));
}

std::string run_description(const replay::LogReader& log) { return replay::describe_run(log.header(), log.run()); }

SideBySide open_side_by_side(const std::vector<std::string>& paths) {
  SideBySide out;
  std::vector<const replay::LogReader*> logs;
  for (const std::string& path : paths) {
    // Every picture is a worker's, with its own reader: these readers only index the runs.
    out.runs.push_back(Session::open_log(path, 0));
    logs.push_back(out.runs.back()->log());
  }
  out.leader_index = leading_run(logs);
  out.leader = std::move(out.runs[out.leader_index]);
  return out;
}

CompareView::CompareView(Viewer& viewer, SideBySide runs, const std::string& backend)
    : viewer_(viewer), panes_(runs.runs.size()), leader_(runs.leader_index) {
  // At most two of the runs draw at a time, at the window's priority (draw_turns.hpp).
  turns_ = std::make_unique<DrawTurns>(kDrawingAtOnce);
  for (std::size_t i = 0; i < panes_.size(); ++i) {
    Pane& p = panes_[i];
    p.own = std::move(runs.runs[i]);
    p.session = i == leader_ ? &viewer_.session() : p.own.get();
    const replay::LogReader& log = *p.session->log();
    p.description = run_description(log);
    p.insertions = insertion_events(log);
    p.phase_steps = steps_per_phase(log);
    // The pictures come from the workers: no scene is built on this thread.
    p.session->defer_pictures(true);
    p.worker = std::make_unique<CanvasWorker>(log.path(), backend, CanvasWorker::Follow::fixed_log, kApproximateFrom,
                                              keep_writes_bytes(panes_.size()), CanvasWorker::Priority::normal, turns_.get());
  }
  for (std::size_t i = 0; i < panes_.size(); ++i)
    for (const auto& [phase, steps] : panes_[i].phase_steps) {
      std::string label = "  " + phase;  // "insert vertices", not "insert_vertices"
      std::replace(label.begin(), label.end(), '_', ' ');
      auto row = std::find_if(phase_rows_.begin(), phase_rows_.end(), [&](const PhaseRow& r) { return r.label == label; });
      if (row == phase_rows_.end()) row = phase_rows_.insert(phase_rows_.end(), PhaseRow{label, {}});
      row->steps[i] += steps;
    }
  start_next_plots();
}

bool CompareView::drawing() const {
  for (const Pane& p : panes_)
    if (p.worker->drawing()) return true;
  return false;
}

// The other runs' plots, one after another: each pass reads a whole log, and four at once
// would hold four logs' writes in memory together (the leader's plots are the viewer's own).
void CompareView::start_next_plots() {
  while (next_plots_ < panes_.size()) {
    Pane& p = panes_[next_plots_];
    if (next_plots_ == leader_) {
      ++next_plots_;
      continue;
    }
    if (!p.plots_started) {
      p.plots.build(p.session->log()->path(), p.session->log()->run().min_angle.value_or(0.0));
      p.plots_started = true;
    }
    if (!p.plots.ready()) return;
    ++next_plots_;
  }
}

bool CompareView::plots_ready() {
  start_next_plots();
  for (std::size_t i = 0; i < panes_.size(); ++i)
    if (i != leader_ && !panes_[i].plots.ready()) return false;
  return true;
}

void CompareView::sync() {
  const Session& lead = *panes_[leader_].session;
  const std::vector<std::uint64_t>& lead_insertions = panes_[leader_].insertions;
  const std::uint64_t at = lead.cursor_info().position;
  for (std::size_t i = 0; i < panes_.size(); ++i) {
    if (i == leader_) continue;
    Pane& p = panes_[i];
    const std::uint64_t want = synced_position(*lead.log(), lead_insertions, at, *p.session->log(), p.insertions, mode_);
    if (p.session->cursor_info().position != want) p.session->seek(want);
  }
}

void CompareView::fit(int pane_w, int pane_h) {
  BBox box;
  for (const Pane& p : panes_) {
    const BBox b = log_box(*p.session->log());
    if (!b.empty()) box.add(b.lo), box.add(b.hi);
  }
  // Room for the pictures' captions and legends, as the first picture lays them out.
  const scene::Margins margins = panes_[0].has_picture
                                     ? scene::layout(panes_[0].picture.moment.scene, pane_w, pane_h).margins
                                     : scene::Margins{24.0, 24.0, 24.0, 24.0};
  viewer_.camera_ = scene::Camera::fit(box, pane_w, pane_h, margins);
  viewer_.fit_pending_ = false;
  viewer_.camera_moved_ = false;
}

void CompareView::post(Pane& p) {
  // Every canvas with the leader's look, through the one camera they share.
  p.worker->request(
      CanvasRequest::planar(p.session->cursor_info().position, viewer_.session().options(), viewer_.camera_));
}

// A finished picture: its pixels to the canvas's texture, its numbers to the columns; the
// leader's moment becomes the viewer's session's (its explanation, its statistics).
bool CompareView::take(Pane& p) {
  if (!p.worker->take(p.picture)) return false;
  p.texture.upload(p.picture.image);
  p.stats = p.picture.stats;
  p.shown_position = p.picture.request.position;
  const bool first = !p.has_picture;
  p.has_picture = true;
  differences_stale_ = true;
  // The moment moves into the run's session: the overlay reads its mesh from there, and the
  // leader's is what the viewer's panels speak of.
  p.session->adopt(p.picture.moment);
  if (&p == &panes_[leader_]) {
    viewer_.stats_ = p.picture.stats;
    viewer_.stats_of_build_ = p.session->scene_builds();
    ++viewer_.canvas_renders_;
  }
  // The first picture brings the caption and legend the fit leaves room for.
  if (first && &p == &panes_[0] && !viewer_.camera_moved_) viewer_.fit_pending_ = true;
  return true;
}

void CompareView::differences() {
  if (!difference || !differences_stale_) return;
  for (Pane& p : panes_) p.edges = p.has_picture ? edge_set(p.session->scene().mesh) : EdgeSet{};
  for (std::size_t i = 0; i < panes_.size(); ++i) {
    Pane& p = panes_[i];
    const Pane& other = panes_[compared_with(i)];
    p.different = p.has_picture && other.has_picture ? edges_missing(p.edges, other.edges)
                                                     : std::vector<std::array<Point, 2>>{};
  }
  differences_stale_ = false;
}

void CompareView::settle() {
  sync();
  if (viewer_.camera_.width() <= 1) return;  // no frame yet: no canvases to wait for
  for (int round = 0; round < 2; ++round) {
    for (Pane& p : panes_) post(p);
    for (Pane& p : panes_) {
      p.worker->wait_until_drawn();
      take(p);
    }
    if (!viewer_.fit_pending_) break;
    fit(pane_w_, pane_h_);
  }
  differences();
}

void CompareView::draw_difference(const Pane& p, ImDrawList& draw) const {
  const scene::Camera& camera = viewer_.camera_;
  draw.PushClipRect(ImVec2(p.rect.x, p.rect.y), ImVec2(p.rect.x + p.rect.z, p.rect.y + p.rect.w), true);
  for (const auto& e : p.different) {
    const Point a = camera.to_screen(e[0]), b = camera.to_screen(e[1]);
    draw.AddLine(ImVec2(p.rect.x + static_cast<float>(a.x), p.rect.y + static_cast<float>(a.y)),
                 ImVec2(p.rect.x + static_cast<float>(b.x), p.rect.y + static_cast<float>(b.y)), kDifferenceColor,
                 kDifferenceWidth);
  }
  // The legend says what the colour means, and against which run.
  char text[96];
  std::snprintf(text, sizeof text, "%zu edges run %zu lacks", p.different.size(),
                compared_with(static_cast<std::size_t>(&p - panes_.data())) + 1);
  const ImVec2 size = ImGui::CalcTextSize(text);
  const ImVec2 at(p.rect.x + 8.0f, p.rect.y + p.rect.w - size.y - 8.0f);
  draw.AddRectFilled(ImVec2(at.x - 4.0f, at.y - 3.0f), ImVec2(at.x + size.y + size.x + 10.0f, at.y + size.y + 3.0f),
                     IM_COL32(255, 255, 255, 225), 3.0f);
  draw.AddLine(ImVec2(at.x, at.y + 0.5f * size.y), ImVec2(at.x + size.y, at.y + 0.5f * size.y), kDifferenceColor,
               kDifferenceWidth + 1.0f);
  draw.AddText(ImVec2(at.x + size.y + 6.0f, at.y), IM_COL32(20, 20, 20, 255), text);
  draw.PopClipRect();
}

void CompareView::draw(float x, float y, float w, float h) {
  // The pictures take what the window's frames leave (FramePace). Only frames drawn while
  // pictures are coming count: an idle window sleeps between frames until an event.
  const auto now = std::chrono::steady_clock::now();
  if (last_frame_ != std::chrono::steady_clock::time_point{} && drawing())
    pace_.frame(std::chrono::duration<double>(now - last_frame_).count());
  last_frame_ = now;
  if (pace_.seats() != turns_->seats()) turns_->set_seats(pace_.seats());
  sync();
  start_next_plots();
  place(x, y, w, h);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  // No background of its own: fill_around draws it where no picture lies.
  ImGui::Begin("canvas", nullptr,
               kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                   ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBackground);
  viewer_.canvas_rect_ = ImVec4(x, y, w, h);
  // Two side by side; three or four in two rows of two.
  const int columns = 2, rows = panes_.size() > 2 ? 2 : 1;
  const float cell_w = (w - kGap) / static_cast<float>(columns), cell_h = (h - kGap * (rows - 1)) / static_cast<float>(rows);
  const float caption_h = ImGui::GetTextLineHeightWithSpacing() + 2.0f;
  pane_w_ = std::max(1, static_cast<int>(cell_w));
  pane_h_ = std::max(1, static_cast<int>(cell_h - caption_h));
  scene::Camera& camera = viewer_.camera_;
  if (viewer_.fit_pending_ || camera.width() <= 1) fit(pane_w_, pane_h_);
  else if (camera.width() != pane_w_ || camera.height() != pane_h_) camera.resize(pane_w_, pane_h_);
  std::array<ImVec4, kMaxRunsSideBySide> pictures{};
  std::size_t covered = 0;
  for (std::size_t i = 0; i < panes_.size(); ++i) {
    Pane& p = panes_[i];
    post(p);
    take(p);
    const float cx = x + static_cast<float>(i % 2) * (cell_w + kGap);
    const float cy = y + static_cast<float>(i / 2) * (cell_h + kGap);
    p.rect = ImVec4(cx, cy + caption_h, static_cast<float>(pane_w_), static_cast<float>(pane_h_));
    if (p.has_picture) pictures[covered++] = p.rect;
  }
  differences();
  const ImGuiIO& io = ImGui::GetIO();
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  fill_around(draw, ImVec4(x, y, w, h), pictures.data(), covered, ImGui::GetColorU32(ImGuiCol_WindowBg));
  for (std::size_t i = 0; i < panes_.size(); ++i) {
    Pane& p = panes_[i];
    const float cx = p.rect.x, cy = p.rect.y - caption_h;
    // The caption: the run's number, its description, and which run leads the timeline.
    ImGui::SetCursorScreenPos(ImVec2(cx + 6.0f, cy + 1.0f));
    ImGui::TextColored(heading_color(), "%zu", i + 1);
    ImGui::SameLine();
    ImGui::Text("%s%s", p.description.c_str(), i == leader_ ? "  (the timeline's run)" : "");
    ImGui::SetCursorScreenPos(ImVec2(p.rect.x, p.rect.y));
    ImGui::PushID(static_cast<int>(i));
    if (p.has_picture) opaque_image(p.texture.id(), ImVec2(p.rect.z, p.rect.w));
    else ImGui::InvisibleButton("##pane", ImVec2(p.rect.z, p.rect.w));
    ImGui::PopID();
    if (ImGui::IsItemHovered()) {
      // Linked cameras: a pan or a zoom on any canvas moves them all.
      const Point at{io.MousePos.x - p.rect.x, io.MousePos.y - p.rect.y};
      if (io.MouseWheel != 0.0f) {
        camera.zoom_at(at, std::pow(1.2, static_cast<double>(io.MouseWheel)));
        viewer_.camera_moved_ = true;
      }
      if ((io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f) && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
        camera.pan(io.MouseDelta.x, io.MouseDelta.y);
        viewer_.camera_moved_ = true;
      }
    }
    if (!p.has_picture) {
      const char* waiting = "replaying the run...";
      const ImVec2 size = ImGui::CalcTextSize(waiting);
      draw.AddText(ImVec2(p.rect.x + 0.5f * (p.rect.z - size.x), p.rect.y + 0.5f * p.rect.w), IM_COL32(60, 60, 60, 255),
                   waiting);
    }
    if (difference && p.has_picture) draw_difference(p, draw);
  }
  ImGui::End();
  ImGui::PopStyleVar(2);
}

}  // namespace meshstep::viewer
