// Where the kinds of event the timeline can mark happen (rejected points, big cavities,
// flips): one pass over every event of the log, made on a thread of its own with its own
// reader of the log, so that ticking one of them never holds up the window (a million-point
// log took 1.8 s on the UI thread). Started the first time an event kind is wanted.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "timeline_marks.hpp"

namespace meshstep::viewer {

class EventMarkScan {
 public:
  using Positions = std::array<std::vector<std::uint64_t>, kMarkCount>;

  EventMarkScan() = default;
  EventMarkScan(const EventMarkScan&) = delete;
  EventMarkScan& operator=(const EventMarkScan&) = delete;
  ~EventMarkScan();  // stops the pass (between blocks) and waits for it

  void start(const std::string& log_path);  // once; later calls do nothing
  bool started() const { return thread_.joinable(); }
  bool ready() const { return ready_.load(std::memory_order_acquire); }
  // Per kind, the position just after each of its events, in order (the step kinds' stay
  // empty); moved out once ready(), and empty after.
  Positions take();
  // Why the pass failed ("" if it did not): the positions are then empty.
  const std::string& error() const { return error_; }

 private:
  std::thread thread_;
  std::atomic<bool> ready_{false}, stop_{false};
  Positions positions_;
  std::string error_;
};

}  // namespace meshstep::viewer
