#include "run_plots.hpp"

#include <chrono>
#include <cmath>
#include <exception>
#include <set>

#include "meshstep/refine/quality.hpp"
#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer {

RunPlots::~RunPlots() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void RunPlots::build(const std::string& log_path, double bound) {
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
      std::multiset<double> angles;  // of the live faces
      std::size_t bad = 0;
      const auto sample = [&] {
        triangles_.push_back(static_cast<float>(angles.size()));
        smallest_angle_.push_back(angles.empty() ? NAN : static_cast<float>(*angles.begin()));
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
            if (const auto it = angles.find(a); it != angles.end()) angles.erase(it);
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
