// The viewer's side panel: why this step, the pseudo-code, layers and colours, invariants,
// export, and the statistics with the plots over the whole run.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "compare_view.hpp"
#include "compare_with.hpp"
#include "file_dialog.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/refine/quality.hpp"
#include "meshstep/scene/svg.hpp"
#include "panel_style.hpp"
#include "viewer.hpp"
#include "edit_panel.hpp"

namespace meshstep::viewer {

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
  const std::uint64_t step = session_->cursor_info().completed;  // the plots' points are moments
  for (std::size_t i = 0; i < 3; ++i) {
    if (i == 2 && angle_bound_ <= 0.0) break;
    const std::vector<float>& v = *series[i];
    const std::size_t at = std::min<std::size_t>(step, v.size() - 1);
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s: %.6g", kTitles[i], static_cast<double>(v[at]));
    run_plot_pictures_[i].draw(kTitles[i], v, plots_.generation(), plot_scales_[2 * i], plot_scales_[2 * i + 1],
                               ImVec2(width, 48.0f), at, overlay);
  }
}

const Stats& Viewer::stats() {
  if (stats_of_build_ == session_->scene_builds()) return stats_;
  // A worker's picture brings the numbers of its moment (show_worker_picture).
  if (!worker_) stats_ = measure(session_->scene().mesh, session_->log());
  stats_of_build_ = session_->scene_builds();
  return stats_;
}

void Viewer::draw_side_panel(float x, float y, float w, float h) {
  place(x, y, w, h);
  ImGui::Begin("meshstep", nullptr, kPanelFlags);
  // The file's name: its folder is in the window's title.
  const std::string& title = session_->title();
  const std::size_t slash = title.rfind('/');
  // Another file (Ctrl+O); a small button, so that the line is no taller than its text.
  if (ImGui::SmallButton("Open...")) request_file_dialog();
  edit_button(*this);
  ImGui::SameLine();
  ImGui::TextWrapped("%s", title.c_str() + (slash == std::string::npos ? 0 : slash + 1));
  ImGui::Separator();
  draw_edit_panel(*this);  // the workbench (edit_panel.hpp)
  if (compare_) compare_->draw_panel(w - 24.0f);

  draw_selection_panel();
  ImGui::SetNextItemOpen(explain_open_);
  if ((explain_open_ = ImGui::CollapsingHeader("Why this step?"))) {
    const scene::Explanation& e = session_->explanation();
    ImGui::TextColored(heading_color(), "%s", e.heading.c_str());
    for (const std::string& line : e.lines) ImGui::TextWrapped("%s", line.c_str());
  }

  draw_pseudocode();

  draw_invariants();
  draw_export();

  ImGui::SetNextItemOpen(layers_open_);
  if ((layers_open_ = ImGui::CollapsingHeader("Layers and colours"))) {
    draw_view_controls();
    int color = static_cast<int>(session_->options().color_by);
    static const char* const kColorNames[] = {"none", "smallest angle", "quality (vs bound)", "area", "region", "age"};
    // In 3D the surface is coloured by its heights: the colouring waits for 2D.
    ImGui::BeginDisabled(view3d_.on());
    if (ImGui::Combo(view3d_.on() ? "colour by (2D)" : "colour by (C)", &color, kColorNames, IM_ARRAYSIZE(kColorNames)))
      session_->set_color_by(static_cast<scene::ColorBy>(color));
    ImGui::EndDisabled();
    bool dark = session_->options().theme == scene::Theme::dark;
    if (ImGui::Checkbox("dark theme (T)", &dark)) session_->set_theme(dark ? scene::Theme::dark : scene::Theme::light);
    ImGui::SameLine();
    bool contrast = session_->options().theme == scene::Theme::high_contrast;
    if (ImGui::Checkbox("high contrast (Shift+T)", &contrast)) toggle_high_contrast();
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
  // Last, so that the panels above stay where they were for one run.
  if (!compare_) draw_compare_with(*this, compare_text_, sizeof compare_text_);
  ImGui::End();
}

// The 3D view's switch and orbit (a terrain's run; disabled for others, saying why).
void Viewer::draw_view_controls() {
  const bool available = view3d_.available();
  bool on = view3d_.on();
  ImGui::BeginDisabled(!available);
  if (ImGui::Checkbox("3D view (V)", &on)) set_view_3d(on);
  ImGui::EndDisabled();
  if (!available) {
    ImGui::SameLine();
    ImGui::TextDisabled("(a terrain's run only: it has heights)");
    return;
  }
  if (!on) return;
  Orbit orbit = view3d_.orbit();
  bool changed = false;
  ImGui::SetNextItemWidth(140.0f);
  changed |= ImGui::DragScalar("azimuth (Ctrl+\u2190\u2192)", ImGuiDataType_Double, &orbit.azimuth_deg, 1.0f, nullptr,
                               nullptr, "%.0f\u00B0");
  ImGui::SetNextItemWidth(140.0f);
  static constexpr double kLowest = -90.0, kHighest = 90.0;
  changed |= ImGui::SliderScalar("elevation (Ctrl+\u2191\u2193)", ImGuiDataType_Double, &orbit.elevation_deg, &kLowest,
                                 &kHighest, "%.0f\u00B0");
  ImGui::SetNextItemWidth(140.0f);
  static constexpr double kFlattest = 0.1, kSteepest = 100.0;
  changed |= ImGui::SliderScalar("heights \u00D7 (Z, Shift+Z)", ImGuiDataType_Double, &orbit.z_scale, &kFlattest,
                                 &kSteepest, "%.3g", ImGuiSliderFlags_Logarithmic);
  if (changed) set_orbit(orbit);
  ImGui::TextDisabled("drag: turn; right-drag: pan; wheel: zoom");
  ImGui::Separator();
}

// The running algorithm's pseudo-code, the line of the cursor's event highlighted.
void Viewer::draw_pseudocode() {
  const replay::LogReader* log = session_->log();
  if (!log) return;
  ImGui::SetNextItemOpen(code_open_);
  if (!(code_open_ = ImGui::CollapsingHeader("Pseudo-code"))) return;
  // The moment the canvas and the explanation show (the cursor's, unless a worker draws).
  const std::uint64_t at = session_->shown_position();
  if (at != code_position_) {
    code_ = scene::pseudocode_at(*log, at);
    code_position_ = at;
  }
  if (!code_.code) return;
  ImGui::TextColored(heading_color(), "%s", code_.code->title.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, quiet_text_color());
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
      io::write_file_atomically(file, scene::to_svg(shown_scene(), camera_));
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

}  // namespace meshstep::viewer
