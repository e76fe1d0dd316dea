// meshstep log info: what a replay log holds.
#include <cstdio>
#include <memory>

#include "cmd_log.hpp"
#include "json_line.hpp"
#include "meshstep/replay/operations.hpp"
#include "meshstep/replay/log_reader.hpp"

namespace meshstep::app {
namespace {

struct InfoArgs {
  std::string log;
  bool json = false;
};

int run_info(const InfoArgs& args) {
  return with_log_errors([&] {
    const replay::LogReader log(args.log);
    const replay::LogHeader& h = log.header();
    std::size_t keyframe_bytes = 0;
    for (const auto& k : log.keyframes()) keyframe_bytes += k.stored_size;
    const double per_event = log.event_count() ? static_cast<double>(log.file_size()) / log.event_count() : 0.0;
    const std::vector<replay::OperationSpan> operations = replay::operation_spans(log, args.log);
    if (args.json) {
      std::vector<JsonLine> listed;
      for (const replay::OperationSpan& o : operations) {
        listed.emplace_back();
        listed.back()
            .field("operation", print_operation(o.operation))
            .field("from_step", static_cast<std::size_t>(o.from_step))
            .field("to_step", static_cast<std::size_t>(o.to_step))
            .field("complete", o.complete);
      }
      JsonLine counts;
      for (std::size_t t = 0; t < replay::kEventTypeCount; ++t)
        counts.field(replay::name(static_cast<replay::EventType>(t)), static_cast<std::size_t>(log.counts_by_type()[t]));
      JsonLine j;
      j.field("log", args.log)
          .field("format_version", static_cast<std::size_t>(log.format_version()))
          .field("program_version", h.program_version)
          .field("input", h.input)
          .field("input_hash", h.input_hash)
          .field("algorithm", h.algorithm)
          .field("parameters", h.parameters)
          .field("data_structure", h.data_structure)
          .field("insertion", h.insertion)
          .field("regions", h.regions.size())
          .field("complete", log.complete())
          .field("events", static_cast<std::size_t>(log.event_count()))
          .field("steps", static_cast<std::size_t>(log.step_count()))
          .field("blocks", log.blocks().size())
          .field("keyframes", log.keyframes().size())
          .field("keyframe_bytes", keyframe_bytes)
          .field("file_bytes", static_cast<std::size_t>(log.file_size()))
          .field("bytes_per_event", per_event)
          .object("events_by_type", counts);
      if (!operations.empty()) j.array("operations", listed);
      if (!log.complete()) j.field("incomplete", log.incomplete_reason());
      std::printf("%s\n", j.str().c_str());
    } else {
      std::printf("%s: meshstep replay log, format %u, written by meshstep %s\n", args.log.c_str(),
                  log.format_version(), h.program_version.c_str());
      std::printf("  run:        %s on %s (input hash %s)\n", h.algorithm.c_str(), h.input.c_str(),
                  h.input_hash.c_str());
      std::printf("  parameters: %s\n", h.parameters.c_str());
      if (!operations.empty()) {
        std::printf("  operations: %zu, one after the other on the one mesh\n", operations.size());
        for (std::size_t i = 0; i < operations.size(); ++i)
          std::printf("    %zu. %s (steps %llu to %llu%s)\n", i + 1, print_operation(operations[i].operation).c_str(),
                      static_cast<unsigned long long>(operations[i].from_step),
                      static_cast<unsigned long long>(operations[i].to_step),
                      operations[i].complete ? "" : ", not finished in this log");
      }
      std::printf("  mesh:       %s, insertion by %s\n", h.data_structure.c_str(), h.insertion.c_str());
      if (!h.regions.empty()) std::printf("  regions:    %zu region points (the input's)\n", h.regions.size());
      std::printf("  events:     %llu in %llu steps\n", static_cast<unsigned long long>(log.event_count()),
                  static_cast<unsigned long long>(log.step_count()));
      for (std::size_t t = 0; t < replay::kEventTypeCount; ++t)
        if (log.counts_by_type()[t])
          std::printf("    %-16s %llu\n", replay::name(static_cast<replay::EventType>(t)),
                      static_cast<unsigned long long>(log.counts_by_type()[t]));
      std::printf("  file:       %llu bytes, %.1f per event; %zu blocks, %zu keyframes (%zu bytes)\n",
                  static_cast<unsigned long long>(log.file_size()), per_event, log.blocks().size(),
                  log.keyframes().size(), keyframe_bytes);
      std::printf("  complete:   %s\n", log.complete() ? "yes" : ("no: " + log.incomplete_reason()).c_str());
    }
    if (!log.complete()) print_warning(Verbosity::normal, args.log + ": " + log.incomplete_reason());
    return kExitOk;
  });
}

}  // namespace

Command add_log_info_command(CLI::App& log) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = log.add_subcommand("info", "Header, event counts by type, steps, blocks, keyframes, file size");
  cmd->add_option("LOG", args->log, "Replay log")->required();
  cmd->add_flag("--json", args->json, "One JSON object instead of text");
  return {cmd, [args] { return run_info(*args); }};
}

}  // namespace meshstep::app
