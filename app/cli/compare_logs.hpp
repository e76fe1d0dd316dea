// What `meshstep compare A.mslog B.mslog` reads from each log: the run's description (its
// caption), and the numbers of its last moment, computed from the mesh the log replays to,
// as `refine --stats json` computes them from the mesh the run made.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep::app {

struct LoggedRun {
  std::string path;
  std::string caption;  // "offcenter, min angle 30" (the run description, in short)
  std::string input, input_hash, algorithm, data_structure, insertion;
  std::size_t steiner = 0, triangles = 0, vertices = 0;
  double min_angle = 0.0, max_angle = 0.0;
  std::uint64_t steps = 0;
  // Steps per phase, in the order the phases first begin (a phase that comes back, as in a
  // two-phase algorithm, adds to its first entry).
  std::vector<std::pair<std::string, std::uint64_t>> phase_steps;
  TriMesh mesh;  // the mesh at the end of the log (as `log mesh --step -1` writes it)
};

// Opens the log, checks it as `log verify` does (replayed forward, back and forward, every
// hash and keyframe), and summarizes it. Throws InputError with `log verify`'s words
// ("PATH: the keyframe after event 40 differs ...") for a damaged or incomplete log.
LoggedRun read_logged_run(const std::string& path);

// The comparison as one JSON object ({"runs":[...],"same_input":...}; no newline), and as
// text with a column per run.
std::string logs_json(const std::vector<LoggedRun>& runs);
std::string logs_text(const std::vector<LoggedRun>& runs);

// The warning for logs of different inputs (by the input's hash), or "" when they agree.
std::string different_inputs_warning(const std::vector<LoggedRun>& runs);

}  // namespace meshstep::app
