// report_surface and describe (io/surface_io.hpp): what keeps a triangle surface from being
// a clean 2-manifold.
#include <algorithm>
#include <limits>

#include "meshstep/error.hpp"
#include "meshstep/geometry/collinear3.hpp"
#include "meshstep/io/surface_io.hpp"

namespace meshstep::io {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

bool repeats_a_vertex(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

std::size_t count_duplicates(const std::vector<Triangle>& triangles) {
  std::vector<Triangle> sorted = triangles;
  for (Triangle& t : sorted) std::sort(t.begin(), t.end());
  std::sort(sorted.begin(), sorted.end());
  std::size_t duplicates = 0;
  for (std::size_t i = 1; i < sorted.size(); ++i) duplicates += sorted[i] == sorted[i - 1];
  return duplicates;
}

// A use of an undirected edge by a triangle: the edge's ends in increasing order, and
// whether the triangle runs along it from lo to hi.
struct EdgeUse {
  std::uint32_t lo, hi;
  bool forward;
  friend bool operator<(const EdgeUse& a, const EdgeUse& b) {
    return a.lo != b.lo ? a.lo < b.lo : a.hi < b.hi;
  }
};

// Counts the closed chains of boundary edges. Walks unused edges from vertex to vertex;
// arriving at a vertex already on the current walk closes a loop, which is cut off the
// walk. Two loops touching at one vertex (a "bowtie") so count as two, whichever way the
// walk turns there. Around every vertex of a surface without non-manifold edges there is
// an even number of boundary edges, so every walk ends in loops; a chain left open (only
// beside non-manifold edges) is no loop.
std::size_t count_boundary_loops(const std::vector<EdgeUse>& edges) {
  // The boundary's vertices, numbered 0..n-1, and the edges around each (CSR arrays).
  std::vector<std::uint32_t> vertices;
  vertices.reserve(2 * edges.size());
  for (const EdgeUse& e : edges) {
    vertices.push_back(e.lo);
    vertices.push_back(e.hi);
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  const auto local = [&](std::uint32_t v) {
    return static_cast<std::size_t>(std::lower_bound(vertices.begin(), vertices.end(), v) -
                                    vertices.begin());
  };
  std::vector<std::size_t> first(vertices.size() + 1, 0);
  for (const EdgeUse& e : edges) {
    ++first[local(e.lo) + 1];
    ++first[local(e.hi) + 1];
  }
  for (std::size_t v = 0; v < vertices.size(); ++v) first[v + 1] += first[v];
  std::vector<std::size_t> around(2 * edges.size());
  std::vector<std::size_t> next = first;  // then: the next edge around v to look at
  for (std::size_t i = 0; i < edges.size(); ++i) {
    around[next[local(edges[i].lo)]++] = i;
    around[next[local(edges[i].hi)]++] = i;
  }
  next = first;

  constexpr std::size_t kOffWalk = std::numeric_limits<std::size_t>::max();
  std::vector<char> used(edges.size(), 0);
  std::vector<std::size_t> place(vertices.size(), kOffWalk);  // position on the walk
  std::vector<std::size_t> walk;
  std::size_t loops = 0;
  for (std::size_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    used[start] = 1;
    walk.assign(1, local(edges[start].lo));
    place[walk[0]] = 0;
    std::size_t at = local(edges[start].hi);
    for (;;) {
      if (place[at] != kOffWalk) {
        ++loops;
        while (walk.back() != at) {
          place[walk.back()] = kOffWalk;
          walk.pop_back();
        }
      } else {
        place[at] = walk.size();
        walk.push_back(at);
      }
      while (next[at] < first[at + 1] && used[around[next[at]]]) ++next[at];
      if (next[at] == first[at + 1]) break;  // no edge left here
      const std::size_t e = around[next[at]];
      used[e] = 1;
      const std::size_t lo = local(edges[e].lo);
      at = lo == at ? local(edges[e].hi) : lo;
    }
    for (const std::size_t v : walk) place[v] = kOffWalk;
  }
  return loops;
}

// A triangle's edge in its direction, and the triangle's third corner.
struct Directed {
  std::uint32_t from, to, apex;
  friend bool operator<(const Directed& a, const Directed& b) {
    return a.from != b.from ? a.from < b.from : a.to < b.to;
  }
};

// Counts the boundary loops of a surface whose every edge has at most two triangles, which
// run along it in opposite directions. Each boundary edge, directed as its triangle runs
// along it, is followed by the next boundary edge round the fan of triangles at its end.
// So two loops that touch at a vertex stay two, and a third loop that touches both there
// (a chain walk could pair those edges either way) is counted one way only: cutting an edge
// or flipping one inside the surface never changes the count.
std::size_t count_fan_boundary_loops(const std::vector<Triangle>& triangles) {
  std::vector<Directed> edges;
  edges.reserve(3 * triangles.size());
  for (const Triangle& t : triangles) {
    if (repeats_a_vertex(t)) continue;
    for (std::size_t k = 0; k < 3; ++k) edges.push_back({t[k], t[(k + 1) % 3], t[(k + 2) % 3]});
  }
  std::sort(edges.begin(), edges.end());
  const auto find = [&](std::uint32_t from, std::uint32_t to) -> std::size_t {
    const auto it = std::lower_bound(edges.begin(), edges.end(), Directed{from, to, 0});
    return it != edges.end() && it->from == from && it->to == to ? static_cast<std::size_t>(it - edges.begin())
                                                                : edges.size();
  };
  constexpr std::size_t kNotBoundary = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> next(edges.size(), kNotBoundary);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (find(edges[i].to, edges[i].from) != edges.size()) continue;  // an inner edge
    // Round the fan at `to`: leave by the triangle's next edge, and cross each inner edge
    // into the triangle beyond, until an edge has no triangle beyond it.
    const std::uint32_t v = edges[i].to;
    std::size_t e = find(v, edges[i].apex);
    for (std::size_t turns = 0; turns <= edges.size(); ++turns) {
      const std::size_t back = find(edges[e].to, v);
      if (back == edges.size()) break;
      e = find(v, edges[back].apex);
    }
    next[i] = e;
  }
  std::vector<char> seen(edges.size(), 0);
  std::size_t loops = 0;
  for (std::size_t start = 0; start < edges.size(); ++start) {
    if (next[start] == kNotBoundary || seen[start]) continue;
    std::size_t e = start;
    while (e != kNotBoundary && e < edges.size() && !seen[e]) {
      seen[e] = 1;
      e = next[e];
    }
    loops += e == start;
  }
  return loops;
}

}  // namespace

bool SurfaceReport::clean() const {
  return degenerate_triangles == 0 && duplicate_triangles == 0 && non_manifold_edges == 0 &&
         inconsistent_edges == 0 && unused_vertices == 0;
}

SurfaceReport report_surface(const Surface& s) {
  SurfaceReport r;
  std::vector<char> used(s.vertices.size(), 0);
  std::vector<EdgeUse> uses;
  uses.reserve(3 * s.triangles.size());
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const Triangle& t = s.triangles[i];
    for (const std::uint32_t v : t) {
      if (v >= s.vertices.size()) {
        throw InputError("triangle " + std::to_string(i) + " uses vertex " + std::to_string(v) +
                         ", but there are only " + std::to_string(s.vertices.size()) +
                         " vertices");
      }
      used[v] = 1;
    }
    if (repeats_a_vertex(t)) {
      ++r.degenerate_triangles;
      continue;  // its "edges" include one from a vertex to itself: not a surface's
    }
    if (collinear(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]])) ++r.degenerate_triangles;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), a < b});
    }
  }
  r.unused_vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
  r.duplicate_triangles = count_duplicates(s.triangles);

  std::sort(uses.begin(), uses.end());
  std::vector<EdgeUse> boundary;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && !(uses[i] < uses[j])) ++j;
    const std::size_t count = j - i;
    if (count == 1) boundary.push_back(uses[i]);
    if (count > 2) ++r.non_manifold_edges;
    // Two triangles on opposite sides of an edge run along it in opposite directions.
    if (count == 2 && uses[i].forward == uses[i + 1].forward) ++r.inconsistent_edges;
    i = j;
  }
  r.boundary_edges = boundary.size();
  // Oriented and manifold, the fans decide the loops; otherwise the edges alone do.
  r.boundary_loops = r.non_manifold_edges == 0 && r.inconsistent_edges == 0 ? count_fan_boundary_loops(s.triangles)
                                                                             : count_boundary_loops(boundary);
  return r;
}

std::string describe(const SurfaceReport& r) {
  std::vector<std::string> problems;
  const auto add = [&](std::size_t n, const char* one, const char* many) {
    if (n > 0) problems.push_back(std::to_string(n) + " " + (n == 1 ? one : many));
  };
  add(r.degenerate_triangles, "degenerate triangle", "degenerate triangles");
  add(r.duplicate_triangles, "duplicate triangle", "duplicate triangles");
  add(r.non_manifold_edges, "non-manifold edge (more than two triangles)",
      "non-manifold edges (more than two triangles)");
  add(r.inconsistent_edges, "edge between triangles of opposite orientation",
      "edges between triangles of opposite orientation");
  add(r.unused_vertices, "unused vertex", "unused vertices");
  std::string text = r.clean() ? "clean" : "not clean:";
  for (std::size_t i = 0; i < problems.size(); ++i) {
    text += (i == 0 ? " " : ", ") + problems[i];
  }
  if (r.boundary_edges == 0) return text + "; closed (no boundary)";
  text += "; " + std::to_string(r.boundary_loops) +
          (r.boundary_loops == 1 ? " boundary loop (" : " boundary loops (") +
          std::to_string(r.boundary_edges) + (r.boundary_edges == 1 ? " edge)" : " edges)");
  return text;
}

}  // namespace meshstep::io
