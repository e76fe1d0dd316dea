#include "replay/regions.hpp"

#include <algorithm>
#include <numeric>

#include "meshstep/geometry/predicates.hpp"

namespace meshstep::replay::detail {

namespace {

constexpr std::uint32_t kNoTriangle = ~std::uint32_t{0};

// For each edge 3t + i of each triangle (from its vertex i to vertex i + 1), the triangle
// across it (kNoTriangle on the boundary). Each vertex's corners are gathered (compressed
// rows), and the two half-edges of an edge meet in the star of their shared start: corner
// c at vertex a leaves along (a, next), and the corner d whose previous vertex is that same
// `next` arrives along (next, a). One pass over the stars, each a handful of corners.
//
// The arrays are kept from call to call on each thread: a viewer builds a scene per
// picture, and fresh memory costs more to touch the first time than this whole pass.
const std::vector<std::uint32_t>& neighbours(std::size_t vertex_count,
                                             std::span<const std::array<std::uint32_t, 3>> tris) {
  struct Corner {
    std::uint32_t id, next, prev;
  };
  thread_local std::vector<std::uint32_t> first, corners, filled, across;
  thread_local std::vector<Corner> star;
  first.assign(vertex_count + 1, 0);
  corners.resize(tris.size() * 3);
  for (const auto& t : tris)
    for (const std::uint32_t v : t) ++first[v + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  filled.assign(first.begin(), first.end() - 1);
  for (std::uint32_t t = 0; t < tris.size(); ++t)
    for (std::uint32_t i = 0; i < 3; ++i) corners[filled[tris[t][i]]++] = 3 * t + i;
  across.assign(tris.size() * 3, kNoTriangle);
  for (std::size_t v = 0; v < vertex_count; ++v) {
    star.clear();
    for (std::uint32_t k = first[v]; k < first[v + 1]; ++k) {
      const std::uint32_t c = corners[k], t = c / 3, i = c % 3;
      star.push_back({c, tris[t][(i + 1) % 3], tris[t][(i + 2) % 3]});
    }
    for (const Corner& c : star)
      for (const Corner& d : star)
        if (d.prev == c.next && d.id != c.id) {
          across[c.id] = d.id / 3;                         // c's edge (v, next)
          across[3 * (d.id / 3) + (d.id % 3 + 2) % 3] = c.id / 3;  // d's edge (prev, v)
          break;
        }
  }
  return across;
}

// For each region point, the first triangle (in list order) whose closed triangle holds
// it, kNoTriangle when none does (a point in a hole or outside). Region points are sorted
// by x, so each triangle tests only those within its x range.
std::vector<std::uint32_t> holders(std::span<const Point> points,
                                   std::span<const std::array<std::uint32_t, 3>> triangles,
                                   std::span<const Region> regions) {
  std::vector<std::uint32_t> by_x(regions.size());
  std::iota(by_x.begin(), by_x.end(), 0u);
  std::sort(by_x.begin(), by_x.end(), [&](auto i, auto j) { return regions[i].point.x < regions[j].point.x; });
  std::vector<double> xs(by_x.size());
  for (std::size_t i = 0; i < by_x.size(); ++i) xs[i] = regions[by_x[i]].point.x;

  std::vector<std::uint32_t> holder(regions.size(), kNoTriangle);
  std::size_t found = 0;
  for (std::uint32_t t = 0; t < triangles.size() && found < regions.size(); ++t) {
    const Point &a = points[triangles[t][0]], &b = points[triangles[t][1]], &c = points[triangles[t][2]];
    const auto lo = std::lower_bound(xs.begin(), xs.end(), std::min({a.x, b.x, c.x}));
    const auto hi = std::upper_bound(lo, xs.end(), std::max({a.x, b.x, c.x}));
    for (auto it = lo; it != hi; ++it) {
      const std::uint32_t r = by_x[static_cast<std::size_t>(it - xs.begin())];
      if (holder[r] != kNoTriangle) continue;
      const Point& p = regions[r].point;
      if (orient2d(a, b, p) >= 0.0 && orient2d(b, c, p) >= 0.0 && orient2d(c, a, p) >= 0.0) {
        holder[r] = t;
        ++found;
      }
    }
  }
  return holder;
}

}  // namespace

std::vector<std::uint32_t> region_of_triangles(std::span<const Point> points,
                                               std::span<const std::array<std::uint32_t, 3>> triangles,
                                               std::span<const std::uint8_t> constrained,
                                               std::span<const Region> regions) {
  std::vector<std::uint32_t> region(triangles.size(), 0);
  if (regions.empty() || triangles.empty()) return region;
  const std::vector<std::uint32_t> holder = holders(points, triangles, regions);
  const std::vector<std::uint32_t>& across = neighbours(points.size(), triangles);
  // The last region point to reach a triangle gives its attribute, so the points flood in
  // reverse and a triangle already claimed stops a flood: each triangle is visited once.
  // (A flood fills a whole part between constrained edges, so a part claimed once is
  // claimed whole.)
  thread_local std::vector<std::uint32_t> stack;
  for (std::size_t r = regions.size(); r-- > 0;) {
    if (holder[r] == kNoTriangle || region[holder[r]] != 0) continue;
    const auto claim = static_cast<std::uint32_t>(r + 1);
    region[holder[r]] = claim;
    stack.assign(1, holder[r]);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t u = across[3 * t + i];
        if (constrained[t] >> i & 1 || u == kNoTriangle || region[u] != 0) continue;
        region[u] = claim;
        stack.push_back(u);
      }
    }
  }
  return region;
}

std::vector<double> region_attributes(std::span<const Point> points,
                                      std::span<const std::array<std::uint32_t, 3>> triangles,
                                      std::span<const std::uint8_t> constrained, std::span<const Region> regions) {
  const std::vector<std::uint32_t> region = region_of_triangles(points, triangles, constrained, regions);
  std::vector<double> attribute(triangles.size(), 0.0);
  for (std::size_t t = 0; t < region.size(); ++t)
    if (region[t] != 0) attribute[t] = regions[region[t] - 1].attribute;
  return attribute;
}

}  // namespace meshstep::replay::detail
