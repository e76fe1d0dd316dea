#include "invariant_job.hpp"

#include <exception>

#include "meshstep/error.hpp"

namespace meshstep::viewer {

namespace {

struct Cancelled {};

}  // namespace

InvariantJob::~InvariantJob() { cancel(); }

void InvariantJob::cancel() {
  cancelled_ = true;
  if (thread_.joinable()) thread_.join();
  cancelled_ = false;
}

void InvariantJob::reset() {
  cancel();
  report_.reset();
  error_.clear();
  checked_ = 0;
}

void InvariantJob::start(const std::string& log_path) {
  cancel();
  report_.reset();
  error_.clear();
  checked_ = 0;
  running_ = true;
  thread_ = std::thread([this, log_path] {
    try {
      const replay::LogReader log(log_path);
      replay::InvariantCheckOptions options;
      options.progress = [this](std::uint64_t, std::uint64_t checked) {
        checked_ = checked;
        if (cancelled_) throw Cancelled{};
      };
      report_ = replay::check_invariants(log, options);
    } catch (const Cancelled&) {
      error_ = "cancelled";
    } catch (const std::exception& e) {
      error_ = e.what();
    }
    running_ = false;
  });
}

void InvariantJob::wait() {
  if (thread_.joinable()) thread_.join();
}

const std::optional<replay::InvariantReport>& InvariantJob::report() {
  static const std::optional<replay::InvariantReport> none;
  return running_ ? none : report_;
}

const std::string& InvariantJob::error() {
  static const std::string none;
  return running_ ? none : error_;
}

std::string describe(const replay::InvariantReport& r) {
  if (r.ok) return "valid and delaunay hold at the " + std::to_string(r.checked) + " step boundaries checked";
  std::string out = "step " + std::to_string(r.boundary) + " breaks ";
  for (std::size_t i = 0; i < r.broken.size(); ++i) out += (i ? ", " : "") + std::string(replay::name(r.broken[i].invariant));
  if (!r.broken.empty() && !r.broken.front().problems.empty()) out += ": " + r.broken.front().problems.front();
  if (r.previous_holds) out += " (the mesh after step " + std::to_string(r.boundary - 1) + " holds)";
  return out;
}

}  // namespace meshstep::viewer
