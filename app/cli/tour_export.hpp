// `meshstep export --tour FILE`: a guided tour (docs/tours.md) as a video or numbered frames.
// The tour's run is recorded first; then each stop is drawn with its caption, layers,
// colouring and camera, and held for its seconds (the same picture repeated).
#pragma once

#include <string>

#include "draw_options.hpp"

namespace meshstep::app {

struct TourExportArgs {
  std::string tour, frames, video;
  double fps = 10.0;
  DrawSettings draw;
  bool quiet = false;
};

// Returns the exit status; throws InputError (the tour, its run, its stops), UsageError.
int export_tour(const TourExportArgs& args);

}  // namespace meshstep::app
