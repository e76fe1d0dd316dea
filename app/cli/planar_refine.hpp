// A planar refinement run: `meshstep refine` (one operation) and `meshstep run` (a recipe's
// operations, one after the other on the same mesh). One runner, so that a one-operation
// recipe writes byte for byte what `refine` writes.
#pragma once

#include <string>
#include <vector>

#include "command.hpp"
#include "console.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/run_spec.hpp"

namespace meshstep::app {

// What a finished run made, for a caller that tabulates runs (meshstep compare): the same
// values the run's --stats json prints.
struct PlanarRefineResult {
  TriMesh mesh;
  RefineReport report;
  AngleStats angles;
  std::size_t input_vertices = 0, input_segments = 0;
  double read_ms = 0.0;
};

struct PlanarRefineJob {
  std::string input;   // a .poly or .node, or a mesh PREFIX to refine again
  std::string prefix;  // -o as given; empty: INPUT's default (Triangle's numbering)
  std::string record, stats, max_memory;
  bool no_output = false, write_partial = false;
  Verbosity verbosity = Verbosity::normal;
  // The operations, refine operations all (at least one): the first refines the input,
  // each next one the mesh the one before left (as refine_mesh re-refines).
  std::vector<Operation> operations;
  // Where each operation was written, put before its errors ("RECIPE:LINE: "); none: the
  // command line's own.
  std::vector<std::string> origins;
  std::string recipe;  // the recipe file, an input no output may overwrite (empty: none)
  int refusal_status = kExitUsage;  // the exit status for an operation that cannot be run
  // Filled when the run ends with status 0 (none: only printed).
  PlanarRefineResult* result = nullptr;
};

// Runs the job and reports as `meshstep refine` does; returns the exit status.
int run_planar_refine(const PlanarRefineJob& job);

}  // namespace meshstep::app
