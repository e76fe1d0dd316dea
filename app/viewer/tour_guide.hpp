// A guided tour played in the viewer (`meshstep view --tour FILE`, docs/tours.md): the stops
// resolved against the run's log, Next and Previous (N and P, the tour's buttons, a script's
// `tour next|prev|stop K`), and at a stop its caption on the canvas, its layers, colouring
// and camera. Between stops the person scrubs freely; the caption shows only while the
// cursor stands at the stop's moment, since it speaks of that moment.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/teach/tour.hpp"

namespace meshstep::viewer {

class Viewer;

class TourGuide {
 public:
  // Resolves the stops against the viewer's log; throws InputError("TOUR:LINE: ...").
  TourGuide(teach::Tour tour, const replay::LogReader& log);

  const teach::Tour& tour() const { return tour_; }
  std::size_t stop_count() const { return steps_.size(); }
  // The step each stop shows.
  const std::vector<std::uint64_t>& steps() const { return steps_; }
  // The stop last gone to (0-based).
  std::size_t current() const { return current_; }
  // Whether the cursor stands at the current stop's moment (its caption shows).
  bool at_stop() const { return at_stop_; }

  // Goes to stop i (0-based): the cursor to its step, its layers, colouring, camera and
  // caption. False (and nothing moves) for a stop that does not exist.
  bool go(Viewer& viewer, std::size_t i);
  // The next (previous) stop: from a stop, the one after (before) it; from elsewhere (the
  // person scrubbed), the first stop after (the last before) the cursor. False at the end.
  bool next(Viewer& viewer);
  bool previous(Viewer& viewer);

  // Each frame: the caption on the canvas while the cursor is at the stop, none elsewhere.
  void update(Viewer& viewer);
  // The tour's row on the canvas: Previous, "stop 2 of 7", Next, the tour's title.
  void draw(Viewer& viewer, float x, float y, float width);

 private:
  teach::Tour tour_;
  std::vector<std::uint64_t> steps_;
  std::vector<std::uint64_t> positions_;  // the replay position of each stop's step
  std::size_t current_ = 0;
  bool at_stop_ = false;
};

// The world box a stop's camera shows.
BBox box_of(const teach::CameraBox& camera);

}  // namespace meshstep::viewer
