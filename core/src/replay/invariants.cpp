// log check: the checker's stages at sampled step boundaries, then bisection.
#include "meshstep/replay/invariants.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "check/stages.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/release.hpp"

namespace meshstep::replay {

const char* name(Invariant invariant) {
  switch (invariant) {
    case Invariant::valid: return "valid";
    case Invariant::delaunay: return "delaunay";
    case Invariant::count_: break;
  }
  return "?";
}

std::string invariant_names() {
  std::string names;
  for (std::size_t i = 0; i < kInvariantCount; ++i) {
    if (i) names += ", ";
    names += name(static_cast<Invariant>(i));
  }
  return names;
}

std::vector<Invariant> parse_invariants(const std::string& list) {
  std::vector<Invariant> out;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    const std::string word = list.substr(begin, end - begin);
    std::size_t i = 0;
    while (i < kInvariantCount && word != name(static_cast<Invariant>(i))) ++i;
    if (i == kInvariantCount)
      throw std::invalid_argument((word.empty() ? std::string("an empty invariant name") : "unknown invariant '" + word + "'") +
                                  " (known: " + invariant_names() + ")");
    const auto invariant = static_cast<Invariant>(i);
    if (std::find(out.begin(), out.end(), invariant) == out.end()) out.push_back(invariant);
    if (end == list.size()) return out;
    begin = end + 1;
  }
}

std::vector<BrokenInvariant> check_invariants(const TriMesh& mesh, const std::vector<Invariant>& invariants,
                                              std::size_t max_problems) {
  using namespace check_detail;
  std::array<bool, kInvariantCount> wanted{};
  for (const Invariant i : invariants) wanted[static_cast<std::size_t>(i)] = true;
  const auto want = [&](Invariant i) { return wanted[static_cast<std::size_t>(i)]; };
  std::vector<ProblemLog> logs(kInvariantCount, ProblemLog(max_problems));
  ProblemLog& valid_log = logs[static_cast<std::size_t>(Invariant::valid)];
  ProblemLog& delaunay_log = logs[static_cast<std::size_t>(Invariant::delaunay)];

  // check_mesh's stages, in its order, with the Delaunay stage's problems kept apart from
  // the others (one pass for both invariants). The basic stages run whatever is asked:
  // they decide which triangles the Delaunay stage may trust.
  if (mesh.triangles.size() > EdgeTable::kMaxTriangles || mesh.points.size() >= static_cast<std::size_t>(kNoIndex)) {
    const auto too_large = [&] {
      return "the mesh is too large for the checker (" + std::to_string(mesh.points.size()) + " vertices, " +
             std::to_string(mesh.triangles.size()) + " triangles)";
    };
    for (const Invariant i : invariants) logs[static_cast<std::size_t>(i)].add(too_large);
  } else {
    MeshFacts facts{mesh, valid_log, {}, {}, std::nullopt, {}, std::nullopt};
    check_indices(facts);
    check_orientation(facts);
    std::vector<std::uint8_t> usable(mesh.triangles.size());
    for (std::size_t t = 0; t < usable.size(); ++t) usable[t] = facts.usable(t);
    facts.edges.emplace(mesh, usable);
    release(usable);
    facts.mark_listed_edges();
    if (want(Invariant::valid)) {
      check_edge_use(facts);
      check_winding(facts);
      check_vertices_in_triangles(facts);
      check_neighbors(facts);  // nothing to do for a replayed mesh, which has no neighbors
    }
    if (want(Invariant::delaunay)) {
      MeshFacts delaunay{mesh,
                         delaunay_log,
                         std::move(facts.tri_state),
                         std::move(facts.finite_point),
                         std::move(facts.edges),
                         std::move(facts.listed_edge),
                         std::nullopt};
      check_delaunay(delaunay);
    }
  }

  std::vector<BrokenInvariant> broken;
  std::array<bool, kInvariantCount> reported{};
  for (const Invariant i : invariants) {
    const auto k = static_cast<std::size_t>(i);
    if (reported[k] || logs[k].count() == 0) continue;
    reported[k] = true;
    CheckReport report = std::move(logs[k]).take();
    broken.push_back({i, std::move(report.problems), report.problem_count});
  }
  return broken;
}

InvariantReport check_invariants(const LogReader& log, const InvariantCheckOptions& options) {
  InvariantReport report;
  report.to = std::min(options.to, log.step_count());
  report.from = std::min(options.from, report.to);
  const std::uint64_t span = report.to - report.from;
  Replay replay(log);
  report.stride = options.every ? options.every : 1;
  if (!options.every && span > kAutoSamples) {
    // The meshes in between are taken to grow or shrink evenly from the first to the last.
    replay.seek_step(report.to);
    std::uint64_t faces = replay.live_faces();
    replay.seek_step(report.from);
    faces = std::max<std::uint64_t>(1, (faces + replay.live_faces()) / 2);
    const std::uint64_t samples = std::clamp<std::uint64_t>(kAutoTriangles / faces, 1, kAutoSamples);
    report.stride = (span + samples - 1) / samples;
  }

  const auto check = [&](std::uint64_t boundary) {
    replay.seek_step(boundary);
    std::vector<BrokenInvariant> broken = check_invariants(replay.mesh(), options.invariants, options.max_problems);
    ++report.checked;
    if (options.progress) options.progress(boundary, report.checked);
    return broken;
  };

  // The samples: from, from + stride, ..., and `to`, until one fails.
  bool any_holds = false;
  std::uint64_t holds = report.from;  // the last sample that holds
  std::uint64_t boundary = report.from;
  std::vector<BrokenInvariant> broken;
  for (;;) {
    broken = check(boundary);
    if (!broken.empty()) break;
    any_holds = true;
    holds = boundary;
    if (boundary == report.to) return report;
    boundary = report.to - boundary > report.stride ? boundary + report.stride : report.to;
  }

  // Bisection between the last sample that holds and the first that fails. It assumes that
  // an invariant, once broken, stays broken until proven otherwise: a mesh that breaks one
  // and heals again between two samples can hide an earlier failure, and then the boundary
  // found is a first failure after a boundary that holds, not necessarily the first of the
  // run. With stride 1 (--every 1) every boundary is checked and the first failure is exact
  // whatever the invariant does.
  std::uint64_t fails = boundary;
  if (any_holds) {
    while (fails - holds > 1) {
      const std::uint64_t middle = holds + (fails - holds) / 2;
      std::vector<BrokenInvariant> here = check(middle);
      if (here.empty()) {
        holds = middle;
      } else {
        fails = middle;
        broken = std::move(here);
      }
    }
  }
  report.ok = false;
  report.boundary = fails;
  report.previous_holds = any_holds;
  report.broken = std::move(broken);
  return report;
}

}  // namespace meshstep::replay
