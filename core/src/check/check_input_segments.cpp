// Stage 7b: each input segment (a, b) must be the union of mesh edges: a chain from a to b
// (see segment_chain.hpp), each piece listed in mesh.segments when the mesh lists any.
//
// One exception: a segment with no such chain is accepted when it passes through no
// triangle, i.e. it lies (partly) outside the meshed domain, in a hole or outside the
// outer boundary, where the triangulator removed all triangles.
#include <algorithm>

#include "check/segment_chain.hpp"
#include "check/segment_crossing.hpp"
#include "check/stages.hpp"
#include "check/vertex_adjacency.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep::check_detail {
namespace {

class SegmentCheck {
 public:
  SegmentCheck(MeshFacts& facts, const Pslg& input)
      : facts_(facts), input_(input), adjacency_(facts), reps_(facts, adjacency_) {}

  void check(std::size_t k) {
    const Segment& seg = input_.segments[k];
    const std::size_t known = std::min(input_.points.size(), facts_.mesh.points.size());
    if (seg.a >= known || seg.b >= known) {
      facts_.log.add([&] { return name(k) + " refers to a vertex the mesh does not have"; });
      return;
    }
    if (seg.a == seg.b) return;
    if (!facts_.finite_point[seg.a] || !facts_.finite_point[seg.b]) return;  // reported
    const auto& p = facts_.mesh.points;
    if (p[seg.a] == p[seg.b]) return;  // zero length
    // Endpoints stand for the used vertex at their position, if there is one.
    const auto s = reps_.of(seg.a), e = reps_.of(seg.b);
    const std::uint32_t from = s.value_or(seg.a), to = e.value_or(seg.b);

    const bool listing = !facts_.mesh.segments.empty();
    if (s && e) {
      // When the mesh lists segments the chain should consist of listed edges; looking for
      // such a chain first keeps a vertex that merely lies within the tolerance of the
      // line from diverting the walk onto unlisted edges.
      if (listing && find_segment_chain(p, adjacency_, from, to, listed_).found) return;
      const SegmentChain chain = find_segment_chain(p, adjacency_, from, to, any_);
      if (chain.found) {
        if (listing) check_listed(k, chain.vertices);
        return;
      }
    }
    if (const auto t = crossed_triangle(facts_, p[from], p[to])) {
      facts_.log.add([&] {
        return name(k) + " is not covered by mesh edges: it passes through " +
               facts_.triangle(*t);
      });
      return;
    }
    // Outside the domain, at least in part (it passes through no triangle): what it has
    // inside must be listed, as far as it reaches from either end, where its pieces lie
    // exactly on its line. Within the tolerance alone, a walk from an end cannot tell
    // pieces from other edges near a long segment that leaves the domain at a glancing
    // angle (one 1e7 long admits vertices 1e-2 off its line).
    if (!listing) return;
    if (s) check_listed(k, exactly_on(from, to, find_segment_chain(p, adjacency_, from, to, any_).vertices));
    if (e) check_listed(k, exactly_on(to, from, find_segment_chain(p, adjacency_, to, from, any_).vertices));
  }

  // The chain up to its first vertex off the line from a to b (orient2d != 0).
  std::vector<std::uint32_t> exactly_on(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t> chain) const {
    const auto& p = facts_.mesh.points;
    const auto off = std::find_if(chain.begin(), chain.end(), [&](std::uint32_t v) { return orient2d(p[a], p[b], p[v]) != 0.0; });
    chain.erase(off, chain.end());
    return chain;
  }

 private:
  std::string name(std::size_t k) const {
    const Segment& s = input_.segments[k];
    return "input segment " + number(k, input_.first_index) + " (vertices " +
           number(s.a, input_.first_index) + " " + number(s.b, input_.first_index) + ")";
  }

  void check_listed(std::size_t k, const std::vector<std::uint32_t>& chain) {
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const std::uint32_t v = chain[i], w = chain[i + 1];
      if (facts_.is_listed(v, w)) continue;
      facts_.log.add([&] {
        return name(k) + ": its piece (" + facts_.vertex(std::min(v, w)) + " " +
               facts_.vertex(std::max(v, w)) +
               ") is a mesh edge but is not listed in the mesh segments";
      });
    }
  }

  MeshFacts& facts_;
  const Pslg& input_;
  const Adjacency adjacency_;
  Representatives reps_;
  const EdgeFilter any_ = [](std::uint32_t, std::uint32_t) { return true; };
  const EdgeFilter listed_ = [this](std::uint32_t v, std::uint32_t w) {
    return facts_.is_listed(v, w);
  };
};

}  // namespace

void check_input_segments(MeshFacts& facts, const Pslg& input) {
  if (input.segments.empty()) return;
  SegmentCheck check(facts, input);
  for (std::size_t k = 0; k < input.segments.size(); ++k) check.check(k);
}

}  // namespace meshstep::check_detail
