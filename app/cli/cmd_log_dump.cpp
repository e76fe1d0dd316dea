// meshstep log dump: the events of a replay log as text or JSON Lines.
#include <cstdio>
#include <memory>

#include "cmd_log.hpp"
#include "meshstep/replay/describe.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/step_numbers.hpp"

namespace meshstep::app {
namespace {

struct DumpArgs {
  std::string log;
  std::uint64_t from = 0;
  std::int64_t to = -1;
  bool jsonl = false;
  bool log_ids = false;
};

int run_dump(const DumpArgs& args) {
  return with_log_errors([&] {
    const replay::LogReader log(args.log);
    if (!log.complete()) print_warning(Verbosity::normal, args.log + ": " + log.incomplete_reason());
    const std::uint64_t n = log.event_count();
    // Vertices by their output numbers, as every other text names them, unless asked for the
    // log's own ids (the ones `log verify` and the format speak of).
    const replay::LogReader* names = args.log_ids ? nullptr : &log;
    const std::uint64_t end = args.to < 0 ? n : std::min<std::uint64_t>(n, static_cast<std::uint64_t>(args.to) + 1);
    for (std::uint64_t e = args.from; e < end; ++e) {
      const replay::Event event = log.event(e);
      // Step K's events take the mesh after K - 1 steps to the mesh after K (step_numbers.hpp);
      // the preamble's come before step 0.
      const std::uint64_t step = replay::step_of_event_numbered(log, e);
      const bool in_step = step > 0;
      if (args.jsonl) {
        std::printf("%s\n", replay::to_json(event, e, step, in_step, names).c_str());
      } else {
        const std::string where = in_step ? "step " + std::to_string(step) : "preamble";
        std::printf("%llu [%s] %s\n", static_cast<unsigned long long>(e), where.c_str(),
                    replay::describe(event, names).c_str());
      }
    }
    return kExitOk;
  });
}

}  // namespace

Command add_log_dump_command(CLI::App& log) {
  auto args = std::make_shared<DumpArgs>();
  CLI::App* cmd = log.add_subcommand("dump", "Print events, one per line: text, or JSON Lines with --jsonl");
  cmd->add_option("LOG", args->log, "Replay log")->required();
  cmd->add_option("--from", args->from, "First event (0-based)")->capture_default_str();
  cmd->add_option("--to", args->to, "Last event, inclusive (-1: the last one)")->capture_default_str();
  cmd->add_flag("--jsonl", args->jsonl, "One JSON object per event");
  cmd->add_flag("--log-ids", args->log_ids,
                "Name vertices by the log's own ids, not by their numbers in the output's .node");
  return {cmd, [args] { return run_dump(*args); }};
}

}  // namespace meshstep::app
