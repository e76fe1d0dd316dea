// log check: is the mesh of a recorded run valid (and Delaunay) at every step boundary, and
// if not, which step broke it.
//
// The mesh at boundary k is the mesh after k steps (Replay::seek_step(k), `log mesh --step
// k`), checked with the checker of `meshstep check` (check/mesh_check.hpp). Boundaries are
// sampled (all of them for short runs), and between the last sample that holds and the first
// that fails, bisection finds the first failing boundary.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/replay/log_reader.hpp"

namespace meshstep::replay {

enum class Invariant : std::uint8_t {
  valid,     // indices, strict counterclockwise orientation, manifold edges, no overlap
             // (winding around interior vertices, no vertex inside a triangle or an edge)
  delaunay,  // every edge between two triangles that is not constrained is locally
             // Delaunay (exact incircle; cocircular accepted): constrained Delaunay
  count_
};
inline constexpr std::size_t kInvariantCount = static_cast<std::size_t>(Invariant::count_);

const char* name(Invariant invariant);
// "valid, delaunay": every known name, for messages.
std::string invariant_names();
// A comma-separated list of names ("valid,delaunay"), in the order given, without repeats.
// Throws std::invalid_argument naming the unknown name and the known ones.
std::vector<Invariant> parse_invariants(const std::string& list);

// Without --every, runs of up to kAutoSamples steps are checked at every boundary; longer
// runs at about kAutoSamples evenly spaced boundaries (and the last), then by bisection;
// fewer when the meshes are large, so that about kAutoTriangles triangles are checked in
// all (the checker takes about 1.5 microseconds a triangle: 2000 checks of the meshes of a
// 100,000-point triangulation would take 5 minutes; see docs/replay-log.md).
inline constexpr std::uint64_t kAutoSamples = 2000;
inline constexpr std::uint64_t kAutoTriangles = 10'000'000;

struct InvariantCheckOptions {
  std::vector<Invariant> invariants{Invariant::valid, Invariant::delaunay};
  std::uint64_t every = 0;        // check every N-th boundary from `from`; 0: automatic
  std::uint64_t from = 0;         // first boundary checked (clamped to the run)
  std::uint64_t to = UINT64_MAX;  // last boundary checked (clamped to step_count())
  std::size_t max_problems = 20;  // problem descriptions kept per broken invariant
  // Called after each boundary checked, with that boundary and how many have been checked.
  std::function<void(std::uint64_t boundary, std::uint64_t checked)> progress;
};

struct BrokenInvariant {
  Invariant invariant = Invariant::valid;
  // As the checker words them: vertex and triangle numbers are those of the mesh files
  // `log mesh --step K` writes for that boundary.
  std::vector<std::string> problems;  // the first max_problems
  std::size_t problem_count = 0;      // all of them
};

struct InvariantReport {
  std::uint64_t from = 0, to = 0;  // the range of boundaries, clamped
  std::uint64_t stride = 1;        // sampling stride before bisection
  std::uint64_t checked = 0;       // boundaries checked, samples and bisection together
  bool ok = true;
  // When !ok: the first boundary that fails (the mesh after `boundary` steps), so the step
  // that broke it is step boundary - 1 as `log dump` numbers steps (its events run from
  // step_start(boundary - 1) to step_start(boundary) - 1). previous_holds: the boundary
  // before it was checked and holds; false when the range starts broken (boundary == from).
  std::uint64_t boundary = 0;
  bool previous_holds = false;
  std::vector<BrokenInvariant> broken;  // in the order the invariants were asked for
};

// Checks boundaries from..to of the log (all of it by default). Throws InputError when the
// log turns out to be inconsistent (as Replay does).
InvariantReport check_invariants(const LogReader& log, const InvariantCheckOptions& options = {});

// The invariants of one mesh: those it breaks (empty when all hold).
std::vector<BrokenInvariant> check_invariants(const TriMesh& mesh, const std::vector<Invariant>& invariants,
                                              std::size_t max_problems = 20);

}  // namespace meshstep::replay
