// meshstep explain LOG --step K: the viewer's "Why this step?" text in the terminal, for
// handouts, screen readers and tests. Step K is the moment every command means by it (the
// mesh after K steps, replay/step_numbers.hpp): the text explains the step that led there,
// and names vertices by their numbers in the output's .node, as the viewer does.
#include <cstdio>
#include <memory>
#include <string>

#include "cmd_log.hpp"
#include "json_line.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/explain.hpp"

namespace meshstep::app {
namespace {

struct ExplainArgs {
  std::string log;
  std::int64_t step = -2;  // -2: not given
  bool json = false;
};

// A string as a JSON string: quotes and backslashes escaped, control characters dropped
// (the explanation has none; UTF-8 passes as it is).
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

int run_explain(const ExplainArgs& args) {
  return with_log_errors([&] {
    const replay::LogReader log(args.log);
    if (!log.complete()) print_warning(Verbosity::normal, args.log + ": " + log.incomplete_reason());
    if (const std::string refused = replay::step_refusal(log, "--step", args.step); !refused.empty()) {
      print_error(refused);
      return kExitUsage;
    }
    const std::uint64_t step = args.step < 0 ? log.step_count() : static_cast<std::uint64_t>(args.step);
    replay::Replay cursor(log);
    cursor.seek_event(args.step < 0 ? log.event_count() : replay::step_position(log, step));
    const scene::Explanation e = scene::explain_step(cursor);
    if (args.json) {
      std::string lines = "[";
      for (std::size_t i = 0; i < e.lines.size(); ++i) lines += (i ? "," : "") + json_string(e.lines[i]);
      lines += "]";
      const std::string head = JsonLine()
                                   .field("log", args.log)
                                   .field("step", static_cast<std::size_t>(step))
                                   .field("step_count", static_cast<std::size_t>(log.step_count()))
                                   .field("event", static_cast<std::size_t>(cursor.position()))
                                   .field("heading", e.heading)
                                   .str();
      std::printf("%s,\"lines\":%s}\n", head.substr(0, head.size() - 1).c_str(), lines.c_str());
      return kExitOk;
    }
    std::printf("%s\n", e.heading.c_str());
    for (const std::string& line : e.lines) std::printf("  %s\n", line.c_str());
    return kExitOk;
  });
}

}  // namespace

Command add_explain_command(CLI::App& parent) {
  auto args = std::make_shared<ExplainArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "explain", "Say in words what step K of a recorded run did (the viewer's \"Why this step?\" text)");
  cmd->add_option("LOG", args->log, "Replay log (--record)")->required();
  cmd->add_option("--step", args->step,
                  "The step K: the mesh after K steps, as render, export and log mesh number them "
                  "(0: before the first; -1: the last)")
      ->required();
  cmd->add_flag("--json", args->json, "One JSON object: step, heading, lines");
  cmd->footer(
      "Vertices are named by their numbers in the run's output .node (input vertices keep their\n"
      "input file's numbers); a vertex the run removes again is named r1, r2, ...\n"
      "Example:\n"
      "  meshstep refine lesson.poly --min-angle 30 --record l.mslog\n"
      "  meshstep explain l.mslog --step 12");
  return {cmd, [args] { return run_explain(*args); }};
}

}  // namespace meshstep::app
