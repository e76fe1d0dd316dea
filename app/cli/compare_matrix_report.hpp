// What `meshstep compare --algorithms` prints and draws of its matrix of runs: the rows as
// aligned text, CSV or JSON, the summary (each algorithm's Steiner points over the first's),
// and the SVG figure (Steiner points against a swept angle bound, and the distribution of
// the triangles' smallest angles).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "compare_matrix.hpp"

namespace meshstep::app {

struct MatrixSummary {
  // Per label, in the matrix's order: the geometric mean of its Steiner ratios to the first
  // label's, and how many runs went into it.
  std::vector<std::pair<double, std::size_t>> ratios;
  std::size_t peak_rss_bytes = 0, runs = 0;
  unsigned threads = 1;
};

MatrixSummary summarize(const Matrix& m, const std::vector<MatrixRow>& rows, std::size_t peak_rss_bytes,
                        unsigned threads);
// One JSON object (no newline): {"rows":[...],"reference":...,"steiner_ratio_geomean":{...},...}.
std::string matrix_json(const Matrix& m, const std::vector<MatrixRow>& rows, const MatrixSummary& summary);
// A row per run: aligned text for people, or CSV headed by the JSON's keys.
std::string matrix_table(const Matrix& m, const std::vector<MatrixRow>& rows, bool csv);
std::string matrix_summary_text(const Matrix& m, const MatrixSummary& summary);
// The whole SVG document of --plot; `inputs`: how many inputs the rows cover.
std::string matrix_plot_svg(const Matrix& m, const std::vector<MatrixRow>& rows, std::size_t inputs);
// The shortest text that reads back as the same double (30, 22.5, 1e-06).
std::string bound_text(double v);

}  // namespace meshstep::app
