// `meshstep compare --algorithms`: every run of a matrix (algorithm or recipe x input x angle
// bound), on a pool of threads, each in process through the runner `meshstep refine` uses
// (planar_refine.hpp), so that a row holds what that refine run's --stats json says.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "meshstep/refine/run_spec.hpp"
#include "planar_refine.hpp"

namespace meshstep::app {

// One cell of the matrix: a label (the algorithm's name, or the recipe file's), the
// operations to run (one for an algorithm, a recipe's lines), the input, and the angle
// bound of a sweep (NaN: not swept).
struct MatrixRun {
  std::string label, input;
  double sweep_bound = std::numeric_limits<double>::quiet_NaN();
  std::vector<Operation> operations;
  std::vector<std::string> origins;  // "RECIPE:LINE: " per operation (none: the command line)
  std::string recipe;
};

// The matrix: its runs, the labels of its rows (the first is the reference the summary
// divides by), and the bounds of a --min-angle sweep.
struct Matrix {
  std::vector<MatrixRun> runs;
  std::vector<std::string> labels;  // in the command line's order; the first is the reference
  std::vector<double> bounds;       // the sweep's (empty: --min-angle not swept)
};

struct MatrixRow {
  int status = 0;  // the runner's exit status (0: the run ended and the numbers are its)
  PlanarRefineResult result;
  std::size_t vertices = 0;  // of the mesh made
  // Each triangle's smallest angle, in degrees, for the distribution plots (the mesh itself
  // is not kept: a matrix of large runs would hold every mesh at once).
  std::vector<float> smallest_angles;
};

// Runs every cell on `threads` threads (at least 1); rows[i] is runs[i]'s, whatever order the
// runs end in. Errors of a failed run go to standard error as refine prints them.
std::vector<MatrixRow> run_matrix(const std::vector<MatrixRun>& runs, unsigned threads);

// The geometric mean, over the inputs (and bounds) both ran to the end with Steiner points,
// of `label`'s Steiner points over `reference`'s; `pairs` gets how many went in (0: NaN).
double geometric_mean_steiner_ratio(const std::vector<MatrixRun>& runs, const std::vector<MatrixRow>& rows,
                                    const std::string& label, const std::string& reference, std::size_t* pairs);

// "20:34:2" as its values 20, 22, ..., 34, or one number as itself. Throws RunSpecError
// ("--min-angle 20:34: expected START:END:STEP ...") for any other text.
std::vector<double> parse_sweep(const std::string& text);

}  // namespace meshstep::app
