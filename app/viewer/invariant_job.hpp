// The viewer's "check every step" button: `meshstep log check` (replay/invariants.hpp) on
// the open log, on a thread of its own so that the window keeps drawing, with its own
// reader of the log (a LogReader is not shared between threads).
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "meshstep/replay/invariants.hpp"

namespace meshstep::viewer {

class InvariantJob {
 public:
  ~InvariantJob();

  // Starts checking valid and delaunay at every step boundary (sampled and bisected as
  // `log check` does); a job already running is cancelled first.
  void start(const std::string& log_path);
  bool running() const { return running_.load(); }
  // Boundaries checked so far, and of about how many.
  std::uint64_t checked() const { return checked_.load(); }
  // The report once the job has ended (nullopt while it runs or before it starts), or the
  // error that ended it.
  const std::optional<replay::InvariantReport>& report();
  const std::string& error();
  // Waits for the job (scripts).
  void wait();
  // Stops a job running and forgets the last report: as before any start (another log).
  void reset();

 private:
  void cancel();

  std::thread thread_;
  std::atomic<bool> running_{false}, cancelled_{false};
  std::atomic<std::uint64_t> checked_{0};
  // Written by the job before running_ turns false; read after.
  std::optional<replay::InvariantReport> report_;
  std::string error_;
};

// One line for people: "valid, delaunay hold at 66 step boundaries" or "step 12 breaks
// delaunay: ...".
std::string describe(const replay::InvariantReport& report);

}  // namespace meshstep::viewer
