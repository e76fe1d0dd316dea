// The statistics panel's numbers for the mesh a scene shows: counts, Steiner vertices, the
// extreme angles and a histogram of the smallest angles. A scan of every triangle (about
// 0.1 s for two million): the canvas's worker makes them for big runs, off the UI thread.
#pragma once

#include <array>
#include <cstddef>

#include "meshstep/replay/log_reader.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::viewer {

struct Stats {
  std::size_t vertices = 0, triangles = 0, steiner = 0;
  double min_angle = 0.0, max_angle = 0.0;
  std::array<float, 18> histogram{};  // smallest angles, 0-60 degrees in 18 bins
};

// `log` (may be null) tells input vertices from Steiner ones: a log numbers the input's
// first (its input_vertices parameter counts them). Without it every vertex is input.
Stats measure(const scene::MeshLayer& mesh, const replay::LogReader* log);

}  // namespace meshstep::viewer
