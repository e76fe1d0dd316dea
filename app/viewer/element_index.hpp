// The element history's index, built on a thread of its own when a log opens, with its own
// reader of the log, in one pass over its events:
//  - for every vertex, the events that changed the mesh around it: those that name it (its
//    insertion, the flips and splits of its edges, a constraint, its removal), and those
//    that rewrite its faces without naming it: a Bowyer-Watson cavity names only the
//    vertex it inserts, a vertex removal only the vertex removed, so the corners of the
//    faces they write (the cavity's boundary, the removed vertex's link) are indexed by
//    their writes;
//  - for every face slot, the events that wrote it (a triangle's life is a run of writes
//    to its slot: element_story.hpp);
//  - the input segments and their pieces (segment_table.hpp).
#pragma once

#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "index_rows.hpp"
#include "segment_table.hpp"

namespace meshstep::viewer {

class ElementIndex {
 public:
  ~ElementIndex();
  // Builds the index of LOG_PATH; one being built (of another log) is stopped first.
  void build(const std::string& log_path);
  // Stops a build and forgets what was built: not ready() until the next build.
  void reset();
  bool ready() const { return ready_.load(std::memory_order_acquire); }
  // The events (0-based indices) of vertex v, in order; empty until ready().
  std::span<const std::uint32_t> events_of_vertex(std::uint32_t v) const {
    return ready() ? vertices_.row(v) : std::span<const std::uint32_t>{};
  }
  // The events that wrote face slot s, in order; empty until ready().
  std::span<const std::uint32_t> events_of_slot(std::uint32_t s) const {
    return ready() ? slots_.row(s) : std::span<const std::uint32_t>{};
  }
  // Empty until ready().
  const SegmentTable& segments() const { return ready() ? segments_ : kNoSegments; }
  // What building it cost: wall seconds (reading the log included) and bytes held, in all
  // and by part.
  double build_seconds() const { return seconds_; }
  std::size_t bytes() const { return vertices_.bytes() + slots_.bytes() + segments_.bytes(); }
  std::size_t vertex_bytes() const { return vertices_.bytes(); }
  std::size_t slot_bytes() const { return slots_.bytes(); }
  std::size_t segment_bytes() const { return segments_.bytes(); }
  const std::string& error() const { return error_; }

 private:
  void index(const std::string& log_path);
  static const SegmentTable kNoSegments;

  std::thread thread_;
  std::atomic<bool> ready_{false}, stop_{false};
  Rows<std::uint32_t> vertices_, slots_;
  SegmentTable segments_;
  double seconds_ = 0.0;
  std::string error_;
};

}  // namespace meshstep::viewer
