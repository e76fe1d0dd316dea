// meshstep log check: the mesh checked at step boundaries; when it fails, the first step that
// breaks it, found by bisection.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "cmd_log.hpp"
#include "json_line.hpp"
#include "meshstep/replay/invariants.hpp"
#include "meshstep/replay/step_numbers.hpp"

namespace meshstep::app {
namespace {

struct LogCheckArgs {
  std::string log;
  std::string invariants = "valid,delaunay";
  std::int64_t every = 0;
  std::int64_t from = 0;
  std::int64_t to = -1;
  bool json = false;
};

// Progress on a terminal, about twice a second; nothing when standard error is not one.
class CheckProgress {
 public:
  CheckProgress(std::string log, std::uint64_t to) : show_(::isatty(2) != 0), log_(std::move(log)), to_(to) {}
  ~CheckProgress() {
    if (shown_) std::fprintf(stderr, "\r%*s\r", static_cast<int>(width_), "");
  }
  CheckProgress(const CheckProgress&) = delete;
  CheckProgress& operator=(const CheckProgress&) = delete;

  void update(std::uint64_t boundary, std::uint64_t checked) {
    if (!show_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(500)) return;
    last_ = now;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    width_ = static_cast<std::size_t>(std::fprintf(
        stderr, "\rmeshstep: checking %s: the mesh after %llu of %llu steps, %llu checked (%.0f s)   ", log_.c_str(),
        static_cast<unsigned long long>(boundary), static_cast<unsigned long long>(to_),
        static_cast<unsigned long long>(checked), seconds));
    std::fflush(stderr);
    shown_ = true;
  }

 private:
  bool show_, shown_ = false;
  std::string log_;
  std::uint64_t to_;
  std::size_t width_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
};

std::string names(const std::vector<replay::Invariant>& invariants, const char* separator) {
  std::string text;
  for (const replay::Invariant i : invariants) {
    if (!text.empty()) text += separator;
    text += replay::name(i);
  }
  return text;
}

std::string names(const std::vector<replay::BrokenInvariant>& broken, const char* separator) {
  std::vector<replay::Invariant> invariants;
  for (const auto& b : broken) invariants.push_back(b.invariant);
  return names(invariants, separator);
}

// The first few problems, "; "-separated, with how many more there are.
std::string first_problems(const replay::BrokenInvariant& b, std::size_t few) {
  std::string text;
  for (std::size_t i = 0; i < b.problems.size() && i < few; ++i) text += (i ? "; " : "") + b.problems[i];
  const std::size_t shown = std::min(few, b.problems.size());
  if (b.problem_count > shown) text += " (and " + std::to_string(b.problem_count - shown) + " more)";
  return text;
}

int run_log_check(const LogCheckArgs& args) {
  std::vector<replay::Invariant> invariants;
  try {
    invariants = replay::parse_invariants(args.invariants);
  } catch (const std::invalid_argument& e) {
    print_error("--invariant " + args.invariants + ": " + e.what());
    return kExitUsage;
  }
  if (args.every < 0) {
    print_error("--every " + std::to_string(args.every) + ": expected a number of steps, 1 or more (0: automatic)");
    return kExitUsage;
  }
  return with_log_errors([&] {
    const replay::LogReader log(args.log);
    if (!log.complete()) print_warning(Verbosity::normal, args.log + ": " + log.incomplete_reason());
    const std::uint64_t steps = log.step_count();
    const std::uint64_t to = args.to == -1 ? steps : static_cast<std::uint64_t>(args.to);
    std::string refused = replay::step_refusal(log, "--from", args.from, false);
    if (refused.empty()) refused = replay::step_refusal(log, "--to", args.to);
    if (refused.empty() && static_cast<std::uint64_t>(args.from) > to)
      refused = args.log + ": --from " + std::to_string(args.from) + " comes after --to " + std::to_string(args.to);
    if (!refused.empty()) {
      print_error(refused);
      return kExitUsage;
    }

    replay::InvariantCheckOptions options;
    options.invariants = invariants;
    options.every = static_cast<std::uint64_t>(args.every);
    options.from = static_cast<std::uint64_t>(args.from);
    options.to = to;
    auto progress = std::make_unique<CheckProgress>(args.log, to);
    options.progress = [&](std::uint64_t boundary, std::uint64_t checked) { progress->update(boundary, checked); };
    const replay::InvariantReport r = replay::check_invariants(log, options);
    progress.reset();  // clears its line before the result

    const std::string asked = names(invariants, ",");
    // The step that broke it (step_numbers.hpp): step K takes the mesh after K - 1 steps to
    // the mesh after K, so it is the boundary that fails; boundary 0 is before the first step.
    const bool in_step = !r.ok && r.boundary > 0;
    const std::uint64_t step = in_step ? r.boundary : 0;
    const std::uint64_t first_event = in_step ? log.step_start(step - 1) : 0;
    const std::uint64_t end_event = in_step ? log.step_start(step) : log.step_start(0);
    const std::string kind =
        in_step ? replay::code_name(replay::EventType::step_begin, log.event(first_event).code) : "preamble";

    if (args.json) {
      JsonLine j;
      j.field("log", args.log)
          .field("invariants", asked)
          .field("from", static_cast<std::size_t>(r.from))
          .field("to", static_cast<std::size_t>(r.to))
          .field("stride", static_cast<std::size_t>(r.stride))
          .field("checked", static_cast<std::size_t>(r.checked))
          .field("ok", r.ok);
      if (!r.ok) {
        JsonLine broken;
        for (const auto& b : r.broken)
          broken.object(replay::name(b.invariant), JsonLine()
                                                       .field("problem_count", b.problem_count)
                                                       .field("problems", first_problems(b, b.problems.size())));
        j.field("after_steps", static_cast<std::size_t>(r.boundary))
            .field("previous_holds", r.previous_holds);
        if (in_step)  // absent when the mesh before the first step fails
          j.field("step", static_cast<std::size_t>(step))
              .field("first_event", static_cast<std::size_t>(first_event))
              .field("last_event", static_cast<std::size_t>(end_event - 1))
              .field("step_kind", kind);
        j.object("broken", broken);
      }
      std::printf("%s\n", j.str().c_str());
      return r.ok ? kExitOk : kExitBadInput;
    }

    if (r.ok) {
      std::printf("%s: %llu step boundaries checked, %s hold%s at each\n", args.log.c_str(),
                  static_cast<unsigned long long>(r.checked), asked.c_str(), invariants.size() == 1 ? "s" : "");
      if (r.stride > 1)
        std::printf("  (every %llu steps from %llu to %llu: a failure that heals between two of them goes unseen; "
                    "--every 1 checks all)\n",
                    static_cast<unsigned long long>(r.stride), static_cast<unsigned long long>(r.from),
                    static_cast<unsigned long long>(r.to));
      return kExitOk;
    }
    std::string what;
    for (const auto& b : r.broken)  // named when there are several
      what += (what.empty() ? "" : "; and ") +
              (r.broken.size() > 1 ? std::string(replay::name(b.invariant)) + ": " : std::string()) +
              first_problems(b, 3);
    std::string where, before;
    if (!in_step) {
      where = end_event == 0 ? std::string("the mesh before any event")
                             : "the mesh before the first step (after the preamble, events 0.." +
                                   std::to_string(end_event - 1) + ")";
      before = "no step comes before it";
    } else if (!r.previous_holds) {
      where = "the mesh after " + std::to_string(r.boundary) + " steps (the start of the range)";
      before = "check from an earlier step to find the step that broke it";
    } else {
      where = "step " + std::to_string(step) + " (events " + std::to_string(first_event) + ".." +
              std::to_string(end_event - 1) + ", " + kind + ")";
      before = step == 1 ? "the mesh before it (step 0) holds" : "step " + std::to_string(step - 1) + " holds";
    }
    std::printf("%s: %s breaks %s: %s; %s\n", args.log.c_str(), where.c_str(), names(r.broken, ",").c_str(),
                what.c_str(), before.c_str());
    std::printf("  (%llu step boundaries checked; 'meshstep log mesh %s --step %llu' writes that mesh)\n",
                static_cast<unsigned long long>(r.checked), args.log.c_str(),
                static_cast<unsigned long long>(r.boundary));
    return kExitBadInput;
  });
}

}  // namespace

Command add_log_check_command(CLI::App& log) {
  auto args = std::make_shared<LogCheckArgs>();
  CLI::App* cmd = log.add_subcommand(
      "check",
      "Check the mesh at step boundaries (the mesh after K steps, as 'log mesh --step K' writes it)\n"
      "and, when a check fails, bisect to the first step that breaks it. Invariants: valid\n"
      "(orientation, manifold edges, no overlaps) and delaunay (every unconstrained edge locally\n"
      "Delaunay). Runs of up to 2000 steps are checked at every boundary, longer ones at up to\n"
      "2000 evenly spaced ones (fewer for large meshes: about 10 million triangles in all).\n"
      "Exit 0 if all hold, 1 if not.");
  cmd->add_option("LOG", args->log, "Replay log")->required();
  cmd->add_option("--invariant", args->invariants, "Comma-separated: valid, delaunay (default valid,delaunay)");
  cmd->add_option("--every", args->every, "Check every N-th boundary, then bisect (default: automatic; 1: all)");
  cmd->add_option("--from", args->from, "First boundary: the mesh after A steps (default 0)");
  cmd->add_option("--to", args->to, "Last boundary: the mesh after B steps (default -1: the end)");
  cmd->add_flag("--json", args->json, "One JSON object instead of text");
  return {cmd, [args] { return run_log_check(*args); }};
}

}  // namespace meshstep::app
