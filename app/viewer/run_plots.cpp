#include "run_plots.hpp"

#include <chrono>
#include <cmath>
#include <exception>
#include <algorithm>
#include <functional>
#include <vector>

#include "meshstep/refine/quality.hpp"
#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer {

namespace {

// The smallest of a multiset of numbers that grows and shrinks: two binary heaps, one of
// the numbers put in and one of those taken out, which cancel when both reach the top.
// A red-black tree (std::multiset) did the same 3 to 5 times slower on a million-point run,
// its nodes scattered over the heap. When the taken-out outnumber the live, both are
// sorted and subtracted, so memory stays within twice the live count.
class SmallestOf {
 public:
  void insert(double x) {
    in_.push_back(x);
    std::push_heap(in_.begin(), in_.end(), std::greater<>());
  }
  void erase(double x) {
    out_.push_back(x);
    std::push_heap(out_.begin(), out_.end(), std::greater<>());
    if (out_.size() > 1024 && 2 * out_.size() > in_.size()) compact();
  }
  std::size_t size() const { return in_.size() - out_.size(); }
  // NAN when empty.
  double smallest() {
    while (!out_.empty() && !in_.empty() && out_.front() == in_.front()) {
      std::pop_heap(in_.begin(), in_.end(), std::greater<>());
      in_.pop_back();
      std::pop_heap(out_.begin(), out_.end(), std::greater<>());
      out_.pop_back();
    }
    return size() == 0 ? NAN : in_.front();
  }

 private:
  void compact() {
    std::sort(in_.begin(), in_.end());
    std::sort(out_.begin(), out_.end());
    std::vector<double> live;
    live.reserve(in_.size() - out_.size());
    std::set_difference(in_.begin(), in_.end(), out_.begin(), out_.end(), std::back_inserter(live));
    in_.swap(live);  // sorted ascending: a valid min-heap
    out_.clear();
  }
  std::vector<double> in_, out_;  // min-heaps
};

}  // namespace

RunPlots::~RunPlots() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void RunPlots::reset() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  stop_ = false;
  ready_.store(false, std::memory_order_release);
  ++generation_;
  triangles_.clear();
  smallest_angle_.clear();
  bad_.clear();
  seconds_ = 0.0;
  error_.clear();
}

void RunPlots::build(const std::string& log_path, double bound) {
  reset();
  thread_ = std::thread([this, log_path, bound] {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      const replay::LogReader log(log_path);
      const auto& vertices = log.vertices();
      // The smallest angle of a live, finite face (NAN for a ghost or a dead slot).
      const auto angle = [&](const replay::FaceRecord& f) -> double {
        if (f.dead() || f.ghost()) return NAN;
        for (const VertexId v : f.v)
          if (v >= vertices.size()) return NAN;
        return quality::shape(vertices[f.v[0]].point, vertices[f.v[1]].point, vertices[f.v[2]].point).min_angle_deg();
      };
      SmallestOf angles;  // of the live faces
      std::size_t bad = 0;
      const auto sample = [&] {
        triangles_.push_back(static_cast<float>(angles.size()));
        smallest_angle_.push_back(static_cast<float>(angles.smallest()));
        bad_.push_back(static_cast<float>(bad));
      };
      const std::uint64_t steps = log.step_count();
      triangles_.reserve(steps + 1);
      smallest_angle_.reserve(steps + 1);
      bad_.reserve(steps + 1);
      // The mesh after k steps (k < steps) is the mesh just before step k's first event;
      // after the last step, the mesh at the end.
      std::uint64_t next_step = 0;
      for (std::uint64_t e = 0; e < log.event_count() && !stop_; ++e) {
        while (next_step < steps && e == log.step_start(next_step)) {
          sample();
          ++next_step;
        }
        for (const replay::SlotWrite& w : log.writes(e)) {
          if (const double a = angle(w.before); !std::isnan(a)) {
            angles.erase(a);
            bad -= bound > 0 && a < bound;
          }
          if (const double a = angle(w.after); !std::isnan(a)) {
            angles.insert(a);
            bad += bound > 0 && a < bound;
          }
        }
      }
      while (next_step <= steps && !stop_) {  // the end of the run
        sample();
        ++next_step;
      }
    } catch (const std::exception& e) {
      error_ = e.what();
    }
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ready_.store(true, std::memory_order_release);
  });
}

}  // namespace meshstep::viewer
