#include "tour_guide.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "meshstep/replay/step_numbers.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

BBox box_of(const teach::CameraBox& camera) {
  BBox box;
  box.add({camera.x0, camera.y0});
  box.add({camera.x1, camera.y1});
  return box;
}

TourGuide::TourGuide(teach::Tour tour, const replay::LogReader& log) : tour_(std::move(tour)) {
  steps_ = teach::resolve_stops(tour_, log);
  for (const std::uint64_t k : steps_) positions_.push_back(replay::step_position(log, k));
}

bool TourGuide::go(Viewer& viewer, std::size_t i) {
  if (i >= steps_.size()) return false;
  const teach::TourStop& stop = tour_.stops[i];
  Session& session = viewer.session();
  if (session.playback().playing) session.toggle_play();
  session.seek(positions_[i]);
  // The stop's look, over the tour's, over the defaults: a stop looks the same however the
  // person came to it, and as `export --tour` draws it (the standard layers: no Voronoi
  // diagram unless the tour asks for it).
  scene::LayerSet layers = scene::LayerSet::standard();
  if (tour_.layers) layers = tour_.layers->apply(layers);
  if (stop.layers) layers = stop.layers->apply(layers);
  for (std::size_t l = 0; l < scene::kLayerCount; ++l) {
    const auto layer = static_cast<scene::Layer>(l);
    session.set_layer(layer, layers.has(layer));
  }
  session.set_color_by(stop.color_by.value_or(tour_.color_by.value_or(scene::ColorBy::none)));
  viewer.fit_box(stop.camera ? std::optional<BBox>(box_of(*stop.camera)) : std::nullopt);
  current_ = i;
  update(viewer);
  return true;
}

bool TourGuide::next(Viewer& viewer) {
  update(viewer);  // the cursor may have moved since the last frame (a script, a key)
  const std::uint64_t here = viewer.session().cursor_info().position;
  if (at_stop_) return go(viewer, current_ + 1);
  for (std::size_t i = 0; i < positions_.size(); ++i)
    if (positions_[i] > here) return go(viewer, i);
  return false;
}

bool TourGuide::previous(Viewer& viewer) {
  update(viewer);
  const std::uint64_t here = viewer.session().cursor_info().position;
  if (at_stop_) return current_ > 0 && go(viewer, current_ - 1);
  for (std::size_t i = positions_.size(); i-- > 0;)
    if (positions_[i] < here) return go(viewer, i);
  return false;
}

void TourGuide::update(Viewer& viewer) {
  Session& session = viewer.session();
  at_stop_ = !positions_.empty() && session.cursor_info().position == positions_[current_];
  session.set_narration(at_stop_ ? tour_.stops[current_].caption : std::string());
}

void TourGuide::draw(Viewer& viewer, float x, float y, float width) {
  ImGui::SetCursorScreenPos(ImVec2(x, y));
  char where[64];
  std::snprintf(where, sizeof where, at_stop_ ? "stop %zu of %zu" : "after stop %zu of %zu", current_ + 1, steps_.size());
  ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.2f, 0.2f, 0.2f, 0.75f));
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 1, 1, 1));
  ImGui::BeginDisabled(at_stop_ && current_ == 0);
  if (ImGui::Button("< Previous stop (P)")) previous(viewer);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::Button(where);  // a label on the same backing as the buttons
  ImGui::SameLine();
  ImGui::BeginDisabled(at_stop_ && current_ + 1 == steps_.size());
  if (ImGui::Button("Next stop (N) >")) next(viewer);
  ImGui::EndDisabled();
  if (!tour_.title.empty() && ImGui::GetCursorScreenPos().x < x + width) {
    ImGui::SameLine();
    ImGui::Button(tour_.title.c_str());
  }
  ImGui::PopStyleColor(2);
}

}  // namespace meshstep::viewer
