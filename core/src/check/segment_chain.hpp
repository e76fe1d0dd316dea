// Finding the chain of mesh edges that covers one input segment.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "check/vertex_adjacency.hpp"
#include "meshstep/geometry/point.hpp"

namespace meshstep::check_detail {

struct SegmentChain {
  bool found = false;
  // found: the chain's vertices from s to e. Otherwise the greedy walk up to where it
  // stopped, so the report can say where coverage breaks.
  std::vector<std::uint32_t> vertices;
};

// A chain of mesh edges from s to e (distinct positions) in which every step moves forward
// along se (or back by less than the tolerance, when no strictly forward chain exists) and
// every vertex lies on se: exactly (orient2d == 0) or within 1e-9 |se| of its line (or 4
// ulps of the endpoints' largest coordinate, if more), which admits rounded crossing
// points of segments. Only edges
// (v, w) with allowed(v, w) are used.
// How far from the line through a and b a vertex may lie and still count as on it: 1e-9
// of |ab|, or 4 ulps of a's and b's largest coordinate when that is more (a segment short
// for its coordinates, 1e-10 long at 1e10, where a rounded crossing cannot come nearer).
double line_tolerance(const Point& a, const Point& b);

using EdgeFilter = std::function<bool(std::uint32_t, std::uint32_t)>;
SegmentChain find_segment_chain(const std::vector<Point>& points, const Adjacency& adjacency,
                                std::uint32_t s, std::uint32_t e, const EdgeFilter& allowed);

}  // namespace meshstep::check_detail
