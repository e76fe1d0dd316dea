// The element history's index: for every vertex, the events that changed the mesh around
// it by naming it (its insertion, the flips and splits of its edges, a constraint, its
// removal), built on a thread of its own when a log opens, with its own reader of the log.
// (A Bowyer-Watson cavity names only the vertex it inserts: the vertices on the cavity's
// boundary are not indexed by it.)
#pragma once

#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace meshstep::viewer {

class ElementIndex {
 public:
  ~ElementIndex();
  void build(const std::string& log_path);
  bool ready() const { return ready_.load(std::memory_order_acquire); }
  // The events (0-based indices) that name vertex v, in order; empty until ready().
  std::span<const std::uint32_t> events_of_vertex(std::uint32_t v) const;
  // What building it cost: wall seconds and bytes held.
  double build_seconds() const { return seconds_; }
  std::size_t bytes() const { return (offsets_.size() + events_.size()) * sizeof(std::uint32_t); }
  const std::string& error() const { return error_; }

 private:
  std::thread thread_;
  std::atomic<bool> ready_{false}, stop_{false};
  // Compressed rows: vertex v's events are events_[offsets_[v] .. offsets_[v + 1]).
  std::vector<std::uint32_t> offsets_, events_;
  double seconds_ = 0.0;
  std::string error_;
};

}  // namespace meshstep::viewer
