#include "check/vertex_adjacency.hpp"

#include <algorithm>

namespace meshstep::check_detail {

Adjacency::Adjacency(const MeshFacts& facts) : start_(facts.mesh.points.size() + 1, 0) {
  const auto& tris = facts.mesh.triangles;
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (facts.usable(t))
      for (std::uint32_t v : tris[t]) start_[v + 1] += 2;
  for (std::size_t v = 0; v + 1 < start_.size(); ++v) start_[v + 1] += start_[v];
  next_.resize(start_.back());
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    if (!facts.usable(t)) continue;
    const auto& tri = tris[t];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = tri[i], w = tri[(i + 1) % 3];
      next_[fill[u]++] = w;
      next_[fill[w]++] = u;
    }
  }
}

std::optional<std::uint32_t> Representatives::of(std::uint32_t v) {
  if (!adjacency_.of(v).empty()) return v;
  const auto& p = facts_.mesh.points;
  auto before = [&](std::uint32_t a, std::uint32_t b) { return lex_less(p[a], p[b]); };
  if (!built_) {
    for (std::uint32_t u = 0; u < p.size(); ++u)
      if (facts_.finite_point[u] && !adjacency_.of(u).empty()) used_.push_back(u);
    std::sort(used_.begin(), used_.end(), before);
    built_ = true;
  }
  const auto it = std::lower_bound(used_.begin(), used_.end(), v, before);
  if (it != used_.end() && p[*it] == p[v]) return *it;
  return std::nullopt;
}

}  // namespace meshstep::check_detail
