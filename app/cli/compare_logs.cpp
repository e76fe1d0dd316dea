// Summaries of recorded runs for `meshstep compare` (compare_logs.hpp).
#include "compare_logs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "compare_table.hpp"
#include "json_line.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/error.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/run_header.hpp"
#include "meshstep/replay/verify.hpp"

namespace meshstep::app {
namespace {

std::string log_file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

}  // namespace

LoggedRun read_logged_run(const std::string& path) {
  const replay::LogReader log(path);
  // The same check and the same words as `log verify`: a log that does not describe one
  // consistent run gives no numbers.
  const replay::VerifyReport verified = replay::verify(log);
  if (!verified.ok) throw InputError(path, 0, verified.problem);

  const replay::LogHeader& h = log.header();
  LoggedRun r;
  r.path = path;
  r.caption = replay::describe_run(h, log.run());
  r.input = h.input;
  r.input_hash = h.input_hash;
  r.algorithm = h.algorithm;
  r.data_structure = h.data_structure;
  r.insertion = log.run().insertion.empty() ? h.insertion : log.run().insertion;
  r.steps = log.step_count();

  replay::Replay cursor(log);
  cursor.seek_event(log.event_count());
  r.mesh = cursor.output_mesh();
  r.triangles = r.mesh.triangles.size();
  r.vertices = r.mesh.points.size();
  const AngleStats angles = angle_stats(r.mesh);
  r.min_angle = angles.min_angle_deg;
  r.max_angle = angles.max_angle_deg;
  // Steiner vertices as refine's report counts them: every vertex the run introduced past
  // the input's and kept (one removed again, near a split segment or by improvement, is
  // counted in removed_vertices instead).
  const std::uint64_t input_vertices = log.run().input_vertices;
  for (std::size_t v = input_vertices; v < log.vertices().size(); ++v) {
    const replay::VertexInfo& info = log.vertices()[v];
    if (info.event == kNone || info.same_as != kNone || info.removed != UINT64_MAX) continue;
    ++r.steiner;
  }

  for (const replay::PhaseSpan& span : log.phases()) {
    const std::uint64_t end = span.end == replay::kNoEnd ? log.event_count() : span.end;
    const std::uint64_t steps = log.completed_steps_at(end) - log.completed_steps_at(span.begin);
    const std::string phase = replay::name(span.phase);
    bool found = false;
    for (auto& [name, count] : r.phase_steps)
      if (name == phase) {
        count += steps;
        found = true;
      }
    if (!found) r.phase_steps.emplace_back(phase, steps);
  }
  return r;
}

std::string different_inputs_warning(const std::vector<LoggedRun>& runs) {
  for (std::size_t i = 1; i < runs.size(); ++i) {
    if (runs[i].input_hash == runs[0].input_hash) continue;
    return runs[0].path + " and " + runs[i].path + " are runs on different inputs (" + runs[0].input + ", hash " +
           runs[0].input_hash + "; " + runs[i].input + ", hash " + runs[i].input_hash +
           "): compared anyway, but their numbers do not measure the algorithms alone";
  }
  return "";
}

std::string logs_json(const std::vector<LoggedRun>& runs) {
  std::string out = "{\"runs\":[";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const LoggedRun& r = runs[i];
    JsonLine phase_steps;
    for (const auto& [name, steps] : r.phase_steps) phase_steps.field(name, static_cast<std::size_t>(steps));
    JsonLine j;
    j.field("log", r.path)
        .field("caption", r.caption)
        .field("input", r.input)
        .field("input_hash", r.input_hash)
        .field("algorithm", r.algorithm)
        .field("ds", r.data_structure)
        .field("insertion", r.insertion)
        .field("vertices", r.vertices)
        .field("triangles", r.triangles)
        .field("steiner", r.steiner)
        .field("min_angle", r.min_angle)
        .field("max_angle", r.max_angle)
        .field("steps", static_cast<std::size_t>(r.steps))
        .object("phase_steps", phase_steps)
        // A log keeps no clock: its run's time is not known here (refine --stats json has it).
        .field("ms", std::nan(""));
    out += (i ? "," : "") + j.str();
  }
  out += std::string("],\"same_input\":") + (different_inputs_warning(runs).empty() ? "true" : "false") + "}";
  return out;
}

std::string logs_text(const std::vector<LoggedRun>& runs) {
  // Every phase any run has, in the order they first appear.
  std::vector<std::string> phases;
  for (const LoggedRun& r : runs)
    for (const auto& [name, steps] : r.phase_steps)
      if (std::find(phases.begin(), phases.end(), name) == phases.end()) phases.push_back(name);
  const auto steps_in = [](const LoggedRun& r, const std::string& phase) -> std::optional<std::uint64_t> {
    for (const auto& [name, steps] : r.phase_steps)
      if (name == phase) return steps;
    return std::nullopt;
  };

  std::vector<std::string> header = {""};
  for (const LoggedRun& r : runs) header.push_back(log_file_name(r.path));
  TextTable table(header);
  const auto row = [&](const std::string& name, auto cell) {
    std::vector<std::string> cells = {name};
    for (const LoggedRun& r : runs) cells.push_back(cell(r));
    table.add_row(cells);
  };
  row("run", [](const LoggedRun& r) { return r.caption; });
  row("input", [](const LoggedRun& r) { return log_file_name(r.input); });
  row("Steiner points", [](const LoggedRun& r) { return std::to_string(r.steiner); });
  row("triangles", [](const LoggedRun& r) { return std::to_string(r.triangles); });
  row("smallest angle", [](const LoggedRun& r) { return fixed(r.min_angle, 2); });
  row("largest angle", [](const LoggedRun& r) { return fixed(r.max_angle, 2); });
  row("steps", [](const LoggedRun& r) { return std::to_string(r.steps); });
  for (const std::string& phase : phases)
    row("  " + phase, [&](const LoggedRun& r) {
      const auto steps = steps_in(r, phase);
      return steps ? std::to_string(*steps) : std::string("-");
    });
  row("time", [](const LoggedRun&) { return std::string("not in the log"); });
  return table.text();
}

}  // namespace meshstep::app
