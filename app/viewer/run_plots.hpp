// The plots over the whole run: after every step, the triangles, the smallest angle and the
// triangles still below the angle bound. Made on a thread of its own when a log opens, by
// one pass over the log's face writes (each write takes its old face out of the tallies and
// puts its new one in), with its own reader of the log.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

namespace meshstep::viewer {

class RunPlots {
 public:
  ~RunPlots();
  // bound: the smallest-angle bound that makes a triangle bad (0: none counted).
  // One being built (of another log) is stopped first.
  void build(const std::string& log_path, double bound);
  // Stops a build and forgets what was built: not ready() until the next build.
  void reset();
  bool ready() const { return ready_.load(std::memory_order_acquire); }
  // Counts the builds (and resets): a picture of the values drawn at one generation is of
  // those values only (the vectors are refilled in place, at the same address).
  std::uint64_t generation() const { return generation_; }

  // One value per step boundary: [k] is the mesh after k steps (k = 0 .. step count).
  const std::vector<float>& triangles() const { return triangles_; }
  const std::vector<float>& smallest_angle() const { return smallest_angle_; }
  const std::vector<float>& bad() const { return bad_; }
  double build_seconds() const { return seconds_; }
  const std::string& error() const { return error_; }

 private:
  std::thread thread_;
  std::atomic<bool> ready_{false}, stop_{false};
  std::vector<float> triangles_, smallest_angle_, bad_;
  double seconds_ = 0.0;
  std::string error_;
  std::uint64_t generation_ = 0;
};

}  // namespace meshstep::viewer
