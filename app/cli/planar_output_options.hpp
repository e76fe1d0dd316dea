// The options `refine` and `run` share, registered once so that the two commands take the
// same words with the same help: where the mesh goes (-o, --no-output), the log (--record),
// the statistics (--stats), the memory budget (--max-memory, --write-partial) and how much
// is said (-q, -v). INPUT stays each command's own (refine also takes 3D surfaces).
#pragma once

#include <CLI/CLI.hpp>

#include "planar_refine.hpp"

namespace meshstep::app {

struct PlanarOutputOptions {
  PlanarRefineJob job;  // input, prefix, record, stats, max_memory, no_output, write_partial
  bool quiet = false, verbose = false;

  // The job as the options left it, its verbosity set from -q and -v.
  PlanarRefineJob read() const {
    PlanarRefineJob out = job;
    out.verbosity = quiet ? Verbosity::quiet : verbose ? Verbosity::verbose : Verbosity::normal;
    return out;
  }
};

void add_planar_output_options(CLI::App& cmd, PlanarOutputOptions& options);

}  // namespace meshstep::app
