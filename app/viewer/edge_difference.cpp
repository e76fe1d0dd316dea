#include "edge_difference.hpp"

#include <algorithm>
#include <iterator>

namespace meshstep::viewer {

namespace {

// Exact comparison (lex_less), no tolerance: equal edges come from equal replayed
// coordinates.
bool before(const Point& p, const Point& q) { return lex_less(p, q); }

bool edge_before(const std::array<Point, 2>& e, const std::array<Point, 2>& f) {
  if (before(e[0], f[0])) return true;
  if (before(f[0], e[0])) return false;
  return before(e[1], f[1]);
}

}  // namespace

EdgeSet edge_set(const scene::MeshLayer& mesh) {
  EdgeSet set;
  set.edges.reserve(3 * mesh.triangles.size());
  const std::size_t n = mesh.points.size();
  for (const auto& t : mesh.triangles) {
    if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
    for (int i = 0; i < 3; ++i) {
      Point p = mesh.points[t[i]], q = mesh.points[t[(i + 1) % 3]];
      if (before(q, p)) std::swap(p, q);
      set.edges.push_back({p, q});
    }
  }
  std::sort(set.edges.begin(), set.edges.end(), edge_before);
  // An inner edge is in two triangles: once is enough.
  set.edges.erase(std::unique(set.edges.begin(), set.edges.end(),
                              [](const auto& e, const auto& f) { return !edge_before(e, f) && !edge_before(f, e); }),
                  set.edges.end());
  return set;
}

std::vector<std::array<Point, 2>> edges_missing(const EdgeSet& a, const EdgeSet& b) {
  std::vector<std::array<Point, 2>> out;
  std::set_difference(a.edges.begin(), a.edges.end(), b.edges.begin(), b.edges.end(), std::back_inserter(out),
                      edge_before);
  return out;
}

}  // namespace meshstep::viewer
