#include "check/edge_table.hpp"

#include <algorithm>

namespace meshstep::check_detail {

EdgeTable::EdgeTable(const TriMesh& mesh, const std::vector<std::uint8_t>& usable)
    : start_(mesh.points.size() + 1, 0), twin_(mesh.triangles.size() * 3, kBoundary) {
  const auto& tris = mesh.triangles;
  // Counting sort by origin: one pass to size the buckets, one to fill them.
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (usable[t])
      for (std::uint32_t v : tris[t]) ++start_[v + 1];
  for (std::size_t v = 0; v + 1 < start_.size(); ++v) start_[v + 1] += start_[v];
  out_.resize(start_.back());
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    if (!usable[t]) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t from = tris[t][(i + 1) % 3];
      const std::uint32_t to = tris[t][(i + 2) % 3];
      out_[fill[from]++] = {to, static_cast<std::uint32_t>(3 * t + i)};
    }
  }
  for (std::size_t v = 0; v + 1 < start_.size(); ++v)
    std::sort(out_.begin() + static_cast<std::ptrdiff_t>(start_[v]),
              out_.begin() + static_cast<std::ptrdiff_t>(start_[v + 1]),
              [](const Out& a, const Out& b) {
                return a.dest < b.dest || (a.dest == b.dest && a.edge < b.edge);
              });

  // Classify each directed edge from its own bucket: exactly one use each way makes twins.
  for (std::uint32_t v = 0; v < vertex_count(); ++v) {
    const auto edges = out(v);
    for (std::size_t r0 = 0; r0 < edges.size();) {
      std::size_t r1 = r0 + 1;
      while (r1 < edges.size() && edges[r1].dest == edges[r0].dest) ++r1;
      const auto back = out_to(edges[r0].dest, v);
      std::uint32_t result = kNonManifold;
      if (r1 - r0 == 1 && back.size() == 1) result = back[0].edge;
      if (r1 - r0 == 1 && back.empty()) result = kBoundary;
      for (std::size_t r = r0; r < r1; ++r) twin_[edges[r].edge] = result;
      r0 = r1;
    }
  }
}

std::span<const EdgeTable::Out> EdgeTable::out_to(std::uint32_t v, std::uint32_t dest) const {
  const auto edges = out(v);
  const auto range = std::equal_range(edges.begin(), edges.end(), Out{dest, 0},
                                      [](const Out& a, const Out& b) { return a.dest < b.dest; });
  return {range.first, range.second};
}

}  // namespace meshstep::check_detail
