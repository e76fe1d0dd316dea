// The side panel's part for runs side by side (compare_view.hpp): how the runs are synced,
// the difference overlay, the statistics in one column per run, and the angle histograms
// and the plots over the runs on shared axes, so that bars and curves compare by eye.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

#include "compare_view.hpp"
#include "panel_style.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

namespace {

// The plots over a run, the leader's being the viewer's own.
const RunPlots& plots_of(const CompareView::Pane& p, const Viewer& viewer, bool leader) {
  return leader ? viewer.plots() : p.plots;
}

// The run's name left of its histogram or plot, which takes the rest of `width`: written
// over the plot (ImGui's overlay) it covered the tallest bars. Returns the plot's width.
float run_label(std::size_t i, float width) {
  const float label_w = ImGui::CalcTextSize("run 4").x + ImGui::GetStyle().ItemSpacing.x;
  ImGui::AlignTextToFramePadding();
  ImGui::TextColored(heading_color(), "run %zu", i + 1);
  ImGui::SameLine(ImGui::GetCursorStartPos().x + label_w);
  return std::max(8.0f, width - label_w);
}

}  // namespace

void CompareView::draw_panel(float width) {
  if (!ImGui::CollapsingHeader("Runs side by side", ImGuiTreeNodeFlags_DefaultOpen)) return;
  int mode = static_cast<int>(mode_);
  static const char* const kModes[] = {"step", "vertices inserted", "fraction of the run"};
  ImGui::SetNextItemWidth(0.5f * width);
  if (ImGui::Combo("sync by", &mode, kModes, kSyncModeCount)) mode_ = static_cast<SyncMode>(mode);
  ImGui::Checkbox("difference overlay (D)", &difference);
  if (difference)
    ImGui::TextWrapped("Purple: the edges a canvas's mesh has and the other run's lacks (run 1 against run 2, the "
                       "others against run 1), at the synced moment.");

  const int n = static_cast<int>(panes_.size());
  if (ImGui::BeginTable("runs", n + 1, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchSame | ImGuiTableFlags_BordersInnerV)) {
    // The labels' column as wide as its longest label, the rest shared by the runs.
    float label_w = ImGui::CalcTextSize("steps per phase").x;
    for (const PhaseRow& r : phase_rows_) label_w = std::max(label_w, ImGui::CalcTextSize(r.label.c_str()).x);
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, label_w);
    for (int i = 0; i < n; ++i) {
      char name[16];
      std::snprintf(name, sizeof name, "run %d", i + 1);
      ImGui::TableSetupColumn(name);
    }
    ImGui::TableHeadersRow();
    const auto row = [&](const char* label, auto&& cell) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(heading_color(), "%s", label);
      for (int i = 0; i < n; ++i) {
        ImGui::TableNextColumn();
        cell(panes_[static_cast<std::size_t>(i)]);
      }
    };
    // One number a cell, so that four columns fit the panel.
    row("step", [](const Pane& p) { ImGui::Text("%llu", static_cast<unsigned long long>(p.session->cursor_info().step)); });
    row("steps in all", [](const Pane& p) {
      ImGui::Text("%llu", static_cast<unsigned long long>(p.session->cursor_info().step_count));
    });
    row("vertices in", [](const Pane& p) {
      ImGui::Text("%llu", static_cast<unsigned long long>(inserted_vertices(p.insertions, p.session->cursor_info().position)));
    });
    row("Steiner", [](const Pane& p) { ImGui::Text("%zu", p.stats.steiner); });
    row("triangles", [](const Pane& p) { ImGui::Text("%zu", p.stats.triangles); });
    row("smallest", [](const Pane& p) { ImGui::Text("%.1f\u00B0", p.stats.min_angle); });
    row("largest", [](const Pane& p) { ImGui::Text("%.1f\u00B0", p.stats.max_angle); });
    // Steps per phase: one row per phase any run has, under a heading of their own.
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextDisabled("steps per phase");
    for (const PhaseRow& r : phase_rows_) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(heading_color(), "%s", r.label.c_str());
      for (int i = 0; i < n; ++i) {
        ImGui::TableNextColumn();
        ImGui::Text("%llu", static_cast<unsigned long long>(r.steps[static_cast<std::size_t>(i)]));
      }
    }
    if (difference) row("edges apart", [](const Pane& p) { ImGui::Text("%zu", p.different.size()); });
    ImGui::EndTable();
  }

  // The smallest angles' histograms on one axis: the same height for the same count.
  float most = 1.0f;
  for (const Pane& p : panes_)
    for (const float v : p.stats.histogram) most = std::max(most, v);
  ImGui::TextDisabled("smallest angle per triangle, 0-60\u00B0 (one scale)");
  for (std::size_t i = 0; i < panes_.size(); ++i) {
    const float plot_w = run_label(i, width);
    ImGui::PushID(static_cast<int>(i));
    ImGui::PlotHistogram("##hist", panes_[i].stats.histogram.data(), static_cast<int>(panes_[i].stats.histogram.size()),
                         0, nullptr, 0.0f, most, ImVec2(plot_w, 36.0f));
    ImGui::PopID();
  }

  // The plots over the runs on shared axes: one scale of values, and one of steps (a run
  // with half the steps draws half as wide), the cursor's step marked on each.
  std::uint64_t longest = 1;
  for (const Pane& p : panes_) longest = std::max<std::uint64_t>(longest, p.session->log()->step_count());
  static constexpr const char* kTitles[] = {"triangles", "smallest angle"};
  bool all_ready = true;
  for (std::size_t i = 0; i < panes_.size(); ++i) all_ready = all_ready && plots_of(panes_[i], viewer_, i == leader_).ready();
  if (!all_ready) {
    ImGui::TextDisabled("plotting the runs...");
    return;
  }
  if (!plot_scales_known_) {
    // Once, when every run's plots are ready (a scan of every value of every run).
    for (int k = 0; k < 2; ++k) {
      float lo = FLT_MAX, hi = -FLT_MAX;
      for (std::size_t i = 0; i < panes_.size(); ++i) {
        const RunPlots& plots = plots_of(panes_[i], viewer_, i == leader_);
        for (const float v : k == 0 ? plots.triangles() : plots.smallest_angle())
          if (!std::isnan(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      }
      plot_scales_[2 * k] = lo;
      plot_scales_[2 * k + 1] = hi;
    }
    plot_scales_known_ = true;
  }
  for (int k = 0; k < 2; ++k) {
    const float lo = plot_scales_[2 * k], hi = plot_scales_[2 * k + 1];
    if (lo == FLT_MAX) continue;
    ImGui::TextDisabled("%s over the runs (one scale, %.4g to %.4g)", kTitles[k], static_cast<double>(std::min(lo, 0.0f)),
                        static_cast<double>(hi));
    for (std::size_t i = 0; i < panes_.size(); ++i) {
      const RunPlots& plots = plots_of(panes_[i], viewer_, i == leader_);
      const std::vector<float>& v = k == 0 ? plots.triangles() : plots.smallest_angle();
      if (v.empty()) continue;
      const float plot_w = run_label(i, width);
      const float w = std::max(8.0f, plot_w * static_cast<float>(v.size() - 1) / static_cast<float>(longest));
      const std::size_t at = std::min<std::size_t>(panes_[i].session->cursor_info().completed, v.size() - 1);
      ImGui::PushID(static_cast<int>(i));
      panes_[i].plot_pictures[static_cast<std::size_t>(k)].draw(kTitles[k], v, plots.generation(), std::min(lo, 0.0f), hi,
                                                                 ImVec2(w, 30.0f), at, nullptr);
      ImGui::PopID();
    }
  }
}

}  // namespace meshstep::viewer
