// The matrix of runs of `meshstep compare --algorithms` (compare_matrix.hpp).
#include "compare_matrix.hpp"

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <thread>

#include "meshstep/check/quality.hpp"

namespace meshstep::app {
namespace {

void run_cell(const MatrixRun& run, MatrixRow& row) {
  PlanarRefineJob job;
  job.input = run.input;
  job.no_output = true;
  job.verbosity = Verbosity::quiet;  // the table says what the warnings would
  job.operations = run.operations;
  job.origins = run.origins;
  job.recipe = run.recipe;
  job.refusal_status = kExitBadInput;
  job.result = &row.result;
  row.status = run_planar_refine(job);
  if (row.status != kExitOk) return;
  const TriMesh& mesh = row.result.mesh;
  row.vertices = mesh.points.size();
  row.smallest_angles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    row.smallest_angles.push_back(
        static_cast<float>(triangle_min_angle_deg(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]])));
  row.result.mesh = TriMesh();  // only the numbers stay
}

double parse_number(const std::string& text, const std::string& whole) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
    throw RunSpecError("--min-angle " + whole + ": '" + text + "' is not a number (expected a bound such as 30, "
                       "or a sweep START:END:STEP such as 20:34:2)");
  return value;
}

}  // namespace

std::vector<MatrixRow> run_matrix(const std::vector<MatrixRun>& runs, unsigned threads) {
  std::vector<MatrixRow> rows(runs.size());
  std::atomic<std::size_t> next{0};
  {
    // Each worker takes the next cell until none is left; a row is written by one worker only.
    std::vector<std::jthread> pool;
    for (unsigned t = 0; t < std::max(threads, 1u); ++t)
      pool.emplace_back([&] {
        for (std::size_t i = next++; i < runs.size(); i = next++) run_cell(runs[i], rows[i]);
      });
  }
  return rows;
}

double geometric_mean_steiner_ratio(const std::vector<MatrixRun>& runs, const std::vector<MatrixRow>& rows,
                                    const std::string& label, const std::string& reference, std::size_t* pairs) {
  double log_sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].label != label || rows[i].status != 0 || rows[i].result.report.steiner_vertices == 0) continue;
    for (std::size_t j = 0; j < runs.size(); ++j) {
      if (runs[j].label != reference || runs[j].input != runs[i].input) continue;
      if (!(runs[j].sweep_bound == runs[i].sweep_bound || (std::isnan(runs[j].sweep_bound) && std::isnan(runs[i].sweep_bound))))
        continue;
      if (rows[j].status != 0 || rows[j].result.report.steiner_vertices == 0) continue;
      log_sum += std::log(static_cast<double>(rows[i].result.report.steiner_vertices) /
                          static_cast<double>(rows[j].result.report.steiner_vertices));
      ++n;
    }
  }
  if (pairs) *pairs = n;
  return n ? std::exp(log_sum / static_cast<double>(n)) : std::nan("");
}

std::vector<double> parse_sweep(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t colon; (colon = text.find(':', start)) != std::string::npos; start = colon + 1)
    parts.push_back(text.substr(start, colon - start));
  parts.push_back(text.substr(start));
  if (parts.size() == 1) return {parse_number(parts[0], text)};
  if (parts.size() != 3)
    throw RunSpecError("--min-angle " + text + ": expected one bound (30) or a sweep START:END:STEP (20:34:2)");
  const double first = parse_number(parts[0], text), last = parse_number(parts[1], text),
               step = parse_number(parts[2], text);
  if (step <= 0.0) throw RunSpecError("--min-angle " + text + ": the step must be positive");
  if (last < first) throw RunSpecError("--min-angle " + text + ": the end is below the start");
  // (Counted, not accumulated: 20 + 7 * 2 is 34 exactly, a running sum need not be.)
  const double count = std::floor((last - first) / step + 1e-9) + 1.0;
  if (count > 1000) throw RunSpecError("--min-angle " + text + ": more than 1000 bounds");
  std::vector<double> values;
  for (int i = 0; i < static_cast<int>(count); ++i) values.push_back(first + i * step);
  return values;
}

}  // namespace meshstep::app
