#include "regions.hpp"

#include <algorithm>
#include <numeric>

#include "meshstep/geometry/predicates.hpp"

namespace meshstep::scene::detail {

namespace {

constexpr std::uint32_t kNoTriangle = ~std::uint32_t{0};

// Each vertex's triangles, packed (compressed sparse rows): a triangle's neighbour across
// an edge is found among the few triangles of the edge's first vertex.
struct VertexStars {
  std::vector<std::uint32_t> first, triangles;

  VertexStars(std::size_t vertex_count, std::span<const std::array<std::uint32_t, 3>> tris)
      : first(vertex_count + 1, 0), triangles(tris.size() * 3) {
    for (const auto& t : tris)
      for (const std::uint32_t v : t) ++first[v + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::uint32_t t = 0; t < tris.size(); ++t)
      for (const std::uint32_t v : tris[t]) triangles[next[v]++] = t;
  }

  std::uint32_t across(std::span<const std::array<std::uint32_t, 3>> tris, std::uint32_t t, std::uint32_t a,
                       std::uint32_t b) const {
    for (std::uint32_t i = first[a]; i < first[a + 1]; ++i) {
      const std::uint32_t u = triangles[i];
      if (u != t && std::find(tris[u].begin(), tris[u].end(), b) != tris[u].end()) return u;
    }
    return kNoTriangle;
  }
};

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

std::vector<double> region_attributes(std::span<const Point> points,
                                      std::span<const std::array<std::uint32_t, 3>> triangles,
                                      std::span<const std::pair<std::uint32_t, std::uint32_t>> constrained,
                                      std::span<const Region> regions) {
  std::vector<double> attribute(triangles.size(), 0.0);
  if (regions.empty() || triangles.empty()) return attribute;
  const std::vector<std::uint32_t> holder = holders(points, triangles, regions);
  const VertexStars stars(points.size(), triangles);
  const auto is_constrained = [&](std::uint32_t a, std::uint32_t b) {
    const std::pair<std::uint32_t, std::uint32_t> edge = a < b ? std::pair{a, b} : std::pair{b, a};
    return std::binary_search(constrained.begin(), constrained.end(), edge);
  };
  // The last region point to reach a triangle gives its attribute, so the points flood in
  // reverse and a triangle already claimed stops a flood: each triangle is visited once.
  // (A flood fills a whole part between constrained edges, so a part claimed once is
  // claimed whole.)
  std::vector<bool> claimed(triangles.size(), false);
  std::vector<std::uint32_t> stack;
  for (std::size_t r = regions.size(); r-- > 0;) {
    if (holder[r] == kNoTriangle || claimed[holder[r]]) continue;
    claimed[holder[r]] = true;
    stack.assign(1, holder[r]);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      attribute[t] = regions[r].attribute;
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t a = triangles[t][i], b = triangles[t][(i + 1) % 3];
        if (is_constrained(a, b)) continue;
        const std::uint32_t u = stars.across(triangles, t, a, b);
        if (u == kNoTriangle || claimed[u]) continue;
        claimed[u] = true;
        stack.push_back(u);
      }
    }
  }
  return attribute;
}

}  // namespace meshstep::scene::detail
