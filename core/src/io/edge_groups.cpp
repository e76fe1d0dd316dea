#include "io/edge_groups.hpp"

#include <algorithm>
#include <stdexcept>

#include "meshstep/io/triangle_io.hpp"

namespace meshstep::io::detail {

EdgeGroups group_edges(const TriMesh& mesh) {
  const std::size_t side_count = mesh.triangles.size() * 3;
  if (side_count >= 0xFFFFFFFFu) throw std::length_error("group_edges: too many triangles");

  // Counting sort into buckets by the smaller endpoint, then a sort inside each (small)
  // bucket. Buckets are taken modulo a bound on their number, so that a broken mesh with
  // huge vertex indices costs no more memory than a sound one.
  std::uint32_t max_vertex = 0;
  for (const auto& t : mesh.triangles) max_vertex = std::max({max_vertex, t[0], t[1], t[2]});
  const std::size_t buckets =
      side_count == 0 ? 0 : std::min<std::size_t>(std::size_t{max_vertex} + 1, side_count);
  const bool wrap = buckets <= max_vertex;  // only for a mesh with indices past 3 * triangles
  const auto bucket_of = [&](std::uint32_t side) -> std::size_t {
    const std::uint32_t lo = std::min(side_from(mesh, side), side_to(mesh, side));
    return wrap ? lo % buckets : lo;
  };
  std::vector<std::uint32_t> offset(buckets + 1, 0);
  for (std::uint32_t s = 0; s < side_count; ++s) ++offset[bucket_of(s) + 1];
  for (std::size_t b = 0; b < buckets; ++b) offset[b + 1] += offset[b];

  struct Entry {
    std::uint64_t edge;  // smaller endpoint in the high half, larger in the low half
    std::uint32_t side;
    bool operator<(const Entry& o) const { return edge != o.edge ? edge < o.edge : side < o.side; }
  };
  std::vector<Entry> entries(side_count);
  {
    std::vector<std::uint32_t> fill(offset);  // next free slot of each bucket
    for (std::uint32_t s = 0; s < side_count; ++s) {
      const std::uint32_t a = side_from(mesh, s);
      const std::uint32_t b = side_to(mesh, s);
      const std::uint64_t edge = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      entries[fill[bucket_of(s)]++] = Entry{edge, s};
    }
  }
  EdgeGroups groups;
  groups.sides.reserve(side_count);
  groups.start.reserve(side_count / 2 + 2);
  for (std::size_t b = 0; b < buckets; ++b) {
    const auto first = entries.begin() + offset[b];
    const auto last = entries.begin() + offset[b + 1];
    std::sort(first, last);
    for (auto it = first; it != last; ++it) {
      if (it == first || it->edge != (it - 1)->edge) {
        groups.start.push_back(static_cast<std::uint32_t>(groups.sides.size()));
      }
      groups.sides.push_back(it->side);
    }
  }
  groups.start.push_back(static_cast<std::uint32_t>(groups.sides.size()));
  return groups;
}

}  // namespace meshstep::io::detail

namespace meshstep::io {

std::vector<std::array<std::uint32_t, 3>> compute_neighbors(const TriMesh& mesh) {
  std::vector<std::array<std::uint32_t, 3>> neighbors(mesh.triangles.size(),
                                                      {kNoIndex, kNoIndex, kNoIndex});
  const detail::EdgeGroups groups = detail::group_edges(mesh);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    // An edge of one triangle is on the boundary; one of three or more is not manifold and
    // has no single neighbour: both keep kNoIndex.
    if (groups.start[g + 1] - groups.start[g] != 2) continue;
    const std::uint32_t s = groups.sides[groups.start[g]];
    const std::uint32_t t = groups.sides[groups.start[g] + 1];
    neighbors[s / 3][s % 3] = t / 3;
    neighbors[t / 3][t % 3] = s / 3;
  }
  return neighbors;
}

}  // namespace meshstep::io
