#include "check/segment_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "meshstep/geometry/predicates.hpp"

namespace meshstep::check_detail {

double line_tolerance(const Point& a, const Point& b) {
  const double largest = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y)});
  const double ulp = std::nextafter(largest, std::numeric_limits<double>::infinity()) - largest;
  return std::max(1e-9 * std::hypot(b.x - a.x, b.y - a.y), 4.0 * ulp);
}

namespace {

// The segment se and the rule for one step of a chain along it.
class SegmentLine {
 public:
  SegmentLine(const std::vector<Point>& points, std::uint32_t s, std::uint32_t e)
      : p_(points), s_(s), e_(e), a_(points[s]), b_(points[e]), dx_(b_.x - a_.x), dy_(b_.y - a_.y),
        len2_(dx_ * dx_ + dy_ * dy_), max_cross_(std::sqrt(len2_) * line_tolerance(a_, b_)) {}

  // Position along the segment, scaled by |se|^2: 0 at s, len2 at e.
  double along(std::uint32_t w) const { return (p_[w].x - a_.x) * dx_ + (p_[w].y - a_.y) * dy_; }

  // May a chain step from a vertex at position `from` to w? Forward, strictly; or, with
  // `backtrack`, by less than the tolerance backwards too: crossings rounded within an ulp
  // of each other (many segments through nearly one point) may lie along the segment in
  // another order than the chain of its pieces visits them.
  bool step_ok(double from, std::uint32_t w, bool backtrack = false) const {
    const double to = along(w);
    if (!(to > from) && !(backtrack && to > from - max_cross_ && w != s_)) return false;
    if (w == e_) return true;
    if (!(to < len2_) && !(backtrack && to < len2_ + max_cross_)) return false;  // an intermediate vertex comes before e
    if (orient2d(a_, b_, p_[w]) == 0.0) return true;
    // |cross| / |se| is the distance from the line; compare without dividing.
    return std::fabs(dx_ * (p_[w].y - a_.y) - dy_ * (p_[w].x - a_.x)) <= max_cross_;
  }

 private:
  const std::vector<Point>& p_;
  std::uint32_t s_, e_;
  Point a_, b_;
  double dx_, dy_, len2_, max_cross_;
};

// The usual case: from each vertex take the nearest valid step. In a valid mesh it is the
// only one.
bool greedy(const SegmentLine& line, const Adjacency& adjacency, const EdgeFilter& allowed,
            std::uint32_t s, std::uint32_t e, std::vector<std::uint32_t>& chain) {
  chain.assign(1, s);
  double at = 0.0;
  while (chain.back() != e) {
    std::uint32_t best = e;
    double best_at = std::numeric_limits<double>::infinity();
    bool any = false;
    for (std::uint32_t w : adjacency.of(chain.back())) {
      if (!line.step_ok(at, w) || !allowed(chain.back(), w)) continue;
      const double w_at = line.along(w);
      if (!any || w_at < best_at || (w_at == best_at && w == e)) {
        best = w;
        best_at = w_at;
        any = true;
      }
    }
    if (!any) return false;
    chain.push_back(best);
    at = best_at;
  }
  return true;
}

// The rare case where greedy took a vertex that is within the tolerance of the line but
// leads nowhere, or where the pieces step back by a rounding: search every valid chain. Whether a step is valid depends only on its
// two ends, so plain reachability with a visited set (depth first) decides it.
bool search(const SegmentLine& line, const Adjacency& adjacency, const EdgeFilter& allowed,
            std::uint32_t s, std::uint32_t e, std::vector<std::uint32_t>& chain) {
  std::unordered_map<std::uint32_t, std::uint32_t> parent{{s, s}};
  std::vector<std::uint32_t> stack{s};
  while (!stack.empty()) {
    const std::uint32_t v = stack.back();
    stack.pop_back();
    if (v == e) {
      chain.clear();
      for (std::uint32_t u = e; u != s; u = parent[u]) chain.push_back(u);
      chain.push_back(s);
      std::reverse(chain.begin(), chain.end());
      return true;
    }
    const double at = v == s ? 0.0 : line.along(v);
    for (std::uint32_t w : adjacency.of(v))
      if (!parent.contains(w) && line.step_ok(at, w, true) && allowed(v, w)) {
        parent.emplace(w, v);
        stack.push_back(w);
      }
  }
  return false;
}

}  // namespace

SegmentChain find_segment_chain(const std::vector<Point>& points, const Adjacency& adjacency,
                                std::uint32_t s, std::uint32_t e, const EdgeFilter& allowed) {
  const SegmentLine line(points, s, e);
  SegmentChain result;
  result.found = greedy(line, adjacency, allowed, s, e, result.vertices);
  if (!result.found) {
    std::vector<std::uint32_t> chain;
    if (search(line, adjacency, allowed, s, e, chain)) {
      result.found = true;
      result.vertices = std::move(chain);
    }
  }
  return result;
}

}  // namespace meshstep::check_detail
