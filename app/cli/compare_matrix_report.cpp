// The report of a matrix of runs (compare_matrix_report.hpp).
#include "compare_matrix_report.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "compare_table.hpp"
#include "json_line.hpp"
#include "memory_budget.hpp"
#include "svg_plot.hpp"

namespace meshstep::app {
namespace {

std::string mib(std::size_t bytes) { return fixed(static_cast<double>(bytes) / 1048576.0, 1); }

std::string input_file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// A run's peak memory as the run's own budget accounts for it (memory_budget.hpp: the
// measured peak resident bytes per triangle of a refinement, rounded up): an estimate, the
// same for every algorithm per triangle, since two runs at once share one process's memory.
std::size_t memory_estimate(const MatrixRow& row) {
  return static_cast<std::size_t>(kBytesPerTriangle) * row.smallest_angles.size();
}

double run_ms(const MatrixRow& row) { return row.result.report.triangulate_ms + row.result.report.refine_ms; }

std::string json_rows(const Matrix& m, const std::vector<MatrixRow>& rows) {
  std::string out = "[";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const MatrixRun& run = m.runs[i];
    const RefineReport& r = rows[i].result.report;
    JsonLine ms;
    ms.field("triangulate", r.triangulate_ms).field("refine", r.refine_ms);
    JsonLine j;
    j.field("algorithm", run.label).field("input", run.input);
    if (!std::isnan(run.sweep_bound)) j.field("min_angle_bound", run.sweep_bound);
    j.field("vertices", rows[i].vertices)
        .field("triangles", rows[i].smallest_angles.size())
        .field("steiner", r.steiner_vertices)
        .field("min_angle", rows[i].result.angles.min_angle_deg)
        .field("max_angle", rows[i].result.angles.max_angle_deg)
        .field("below_min_angle", r.below_min_angle)
        .field("bad_triangles", r.bad_triangles)
        .field("bad_near_small_input_angle", r.bad_near_small_input_angle)
        .field("bounds_met", r.bounds_met)
        .field("stopped_by_cap", r.stopped_by_cap)
        .field("memory_estimate_bytes", memory_estimate(rows[i]))
        .object("ms", ms);
    out += (i ? "," : "") + j.str();
  }
  return out + "]";
}

}  // namespace

// Shortest text that reads back as the same double (a bound as the command line gives it:
// 30, 22.5, 1e-06).
std::string bound_text(double v) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}

// Steiner points against the angle bound (summed over the inputs), and the distribution of
// the triangles' smallest angles at the last bound (pooled over the inputs), per algorithm.
std::string matrix_plot_svg(const Matrix& m, const std::vector<MatrixRow>& rows, std::size_t inputs) {
  std::vector<PlotPanel> panels;
  const bool swept = m.bounds.size() > 1;
  char letter = 'a';
  // Panels are lettered when there are two.
  const auto title = [&letter, swept](const std::string& words) {
    return swept ? std::string("(") + letter++ + ") " + words : words;
  };
  if (swept) {
    PlotPanel p;
    p.title = title("Steiner points against the angle bound");
    p.x_label = "angle bound (degrees)";
    p.y_label = inputs > 1 ? "Steiner points (sum over " + std::to_string(inputs) + " inputs)" : "Steiner points";
    p.y_from_zero = true;
    if (m.bounds.size() <= 12) p.x_ticks = m.bounds;  // every bound swept, labelled
    for (const std::string& label : m.labels) {
      PlotSeries s{label, {}, true};
      for (const double bound : m.bounds) {
        double total = 0;
        for (std::size_t i = 0; i < rows.size(); ++i)
          if (m.runs[i].label == label && m.runs[i].sweep_bound == bound)
            total += static_cast<double>(rows[i].result.report.steiner_vertices);
        s.points.emplace_back(bound, total);
      }
      p.series.push_back(std::move(s));
    }
    // One algorithm running away near its limit (circumcenters at 34 degrees: 100 times the
    // others) would flatten every other line against the axis: then the axis is logarithmic.
    double low = std::numeric_limits<double>::infinity(), high = 0.0;
    for (const PlotSeries& s : p.series)
      for (const auto& point : s.points) {
        low = std::min(low, point.second);
        high = std::max(high, point.second);
      }
    p.y_log = low > 0.0 && high > 30.0 * low;
    if (p.y_log) p.y_label += ", log scale";
    panels.push_back(std::move(p));
  }
  PlotPanel cdf;
  const double last = m.bounds.empty() ? std::nan("") : m.bounds.back();
  cdf.title = title(std::isnan(last) ? "Smallest angle of each triangle"
                                     : "Smallest angle of each triangle, bound " + bound_text(last) + "\u00b0");
  cdf.x_label = "smallest angle of a triangle (degrees)";
  cdf.y_label = "fraction of triangles at or below";
  cdf.y_range = std::pair{0.0, 1.0};
  double low = 60.0;
  for (const std::string& label : m.labels) {
    std::vector<float> angles;
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (m.runs[i].label == label && (std::isnan(last) || m.runs[i].sweep_bound == last))
        angles.insert(angles.end(), rows[i].smallest_angles.begin(), rows[i].smallest_angles.end());
    std::sort(angles.begin(), angles.end());
    PlotSeries s{label, {}, false};
    // The empirical CDF as a staircase, thinned to about 600 corners.
    const std::size_t n = angles.size(), stride = std::max<std::size_t>(n / 600, 1);
    for (std::size_t k = 0; k < n; k += stride) {
      const double fraction_before = static_cast<double>(k) / static_cast<double>(n);
      s.points.emplace_back(angles[k], fraction_before);
      const std::size_t next = std::min(k + stride, n);
      s.points.emplace_back(angles[k], static_cast<double>(next) / static_cast<double>(n));
    }
    if (n) {
      low = std::min(low, static_cast<double>(angles.front()));
      s.points.emplace_back(60.0, 1.0);
    }
    cdf.series.push_back(std::move(s));
  }
  cdf.x_range = std::pair{std::floor(low / 5.0) * 5.0, 60.0};
  panels.push_back(std::move(cdf));
  return svg_figure(panels);
}

MatrixSummary summarize(const Matrix& m, const std::vector<MatrixRow>& rows, std::size_t peak_rss_bytes,
                        unsigned threads) {
  MatrixSummary summary;
  summary.peak_rss_bytes = peak_rss_bytes;
  summary.threads = threads;
  summary.runs = rows.size();
  for (const std::string& label : m.labels) {
    std::size_t pairs = 0;
    const double ratio = geometric_mean_steiner_ratio(m.runs, rows, label, m.labels.front(), &pairs);
    summary.ratios.emplace_back(ratio, pairs);
  }
  return summary;
}

std::string matrix_json(const Matrix& m, const std::vector<MatrixRow>& rows, const MatrixSummary& summary) {
  JsonLine ratios;
  for (std::size_t a = 0; a < m.labels.size(); ++a) ratios.field(m.labels[a], summary.ratios[a].first);
  return "{\"rows\":" + json_rows(m, rows) + ",\"reference\":\"" + m.labels.front() +
         "\",\"steiner_ratio_geomean\":" + ratios.str() + ",\"peak_rss_bytes\":" +
         std::to_string(summary.peak_rss_bytes) + "}";
}

std::string matrix_table(const Matrix& m, const std::vector<MatrixRow>& rows, bool csv) {
  const bool swept = !m.bounds.empty();
  // For people: short words; for programs (CSV): the JSON's keys.
  std::vector<std::string> header = {"algorithm", "input"};
  if (swept) header.push_back(csv ? "min_angle_bound" : "bound");
  if (csv)
    for (const char* h : {"steiner", "triangles", "min_angle", "max_angle", "bad_triangles",
                          "bad_near_small_input_angle", "ms", "memory_estimate_kib"})
      header.push_back(h);
  else
    for (const char* h : {"Steiner", "triangles", "min angle", "max angle", "left bad", "at small input angles",
                          "ms", "est. KiB"})
      header.push_back(h);
  TextTable table(header);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RefineReport& r = rows[i].result.report;
    std::vector<std::string> cells = {m.runs[i].label, csv ? m.runs[i].input : input_file_name(m.runs[i].input)};
    if (swept) cells.push_back(bound_text(m.runs[i].sweep_bound));
    const int digits = csv ? 6 : 2;
    cells.push_back(std::to_string(r.steiner_vertices));
    cells.push_back(std::to_string(rows[i].smallest_angles.size()));
    cells.push_back(fixed(rows[i].result.angles.min_angle_deg, digits));
    cells.push_back(fixed(rows[i].result.angles.max_angle_deg, digits));
    cells.push_back(std::to_string(r.bad_triangles));
    cells.push_back(std::to_string(r.bad_near_small_input_angle));
    cells.push_back(fixed(run_ms(rows[i]), csv ? 3 : 1));
    cells.push_back(std::to_string((memory_estimate(rows[i]) + 1023) / 1024));
    table.add_row(std::move(cells));
  }
  return csv ? table.csv() : table.text();
}

std::string matrix_summary_text(const Matrix& m, const MatrixSummary& summary) {
  std::string out = "Steiner points relative to " + m.labels.front() +
                    " (geometric mean of the ratios over the runs both finished):\n";
  char line[256];
  for (std::size_t a = 0; a < m.labels.size(); ++a) {
    std::snprintf(line, sizeof line, "  %-24s %s  (%zu run%s)\n", m.labels[a].c_str(),
                  fixed(summary.ratios[a].first, 3).c_str(), summary.ratios[a].second,
                  summary.ratios[a].second == 1 ? "" : "s");
    out += line;
  }
  std::snprintf(line, sizeof line, "Peak resident memory of this process (all %zu runs, %u at a time): %s MiB\n",
                summary.runs, summary.threads, mib(summary.peak_rss_bytes).c_str());
  return out + line;
}

}  // namespace meshstep::app
