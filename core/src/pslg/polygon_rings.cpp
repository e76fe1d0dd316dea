// pslg_from_rings (pslg/polygon_rings.hpp): the rings' vertices and segments, then one
// hole point per enclosed region that the rings cover an even number of times.
#include "meshstep/pslg/polygon_rings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deque>
#include <unordered_map>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep {
namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

struct PointKey {
  std::uint64_t x, y;
  bool operator==(const PointKey&) const = default;
};
struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const { return std::hash<std::uint64_t>()(k.x * 0x9E3779B97F4A7C15ull ^ k.y); }
};
PointKey key_of(Point p) {
  p.x += 0.0, p.y += 0.0;  // -0 and +0 are one coordinate
  PointKey k;
  std::memcpy(&k.x, &p.x, sizeof k.x);
  std::memcpy(&k.y, &p.y, sizeof k.y);
  return k;
}

// The constrained edges of a mesh around each vertex, in compressed rows (a vertex has few:
// a lookup is a scan of two or three entries, where a hash map cost half the reading time
// of a million-vertex polygon), each with how many times the rings run along it.
struct ConstrainedEdges {
  std::vector<std::size_t> start;  // vertex v's entries: [start[v], start[v + 1])
  std::vector<std::uint32_t> other;
  std::vector<int> uses;

  explicit ConstrainedEdges(const TriMesh& mesh) : start(mesh.points.size() + 1, 0) {
    for (const Segment& s : mesh.segments) ++start[s.a + 1], ++start[s.b + 1];
    for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
    other.resize(start.back());
    uses.assign(start.back(), 0);
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (const Segment& s : mesh.segments) other[next[s.a]++] = s.b, other[next[s.b]++] = s.a;
  }
  // The entry u -> v, or npos when u v is no constrained edge.
  std::size_t find(std::uint32_t u, std::uint32_t v) const {
    for (std::size_t k = start[u]; k < start[u + 1]; ++k)
      if (other[k] == v) return k;
    return npos;
  }
  void add(std::uint32_t u, std::uint32_t v, int n) {
    uses[find(u, v)] += n;
    uses[find(v, u)] += n;
  }
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
};

// How many times the rings run along each constrained edge of `mesh`, the triangulation of
// `pslg` (whose segment s the rings use uses[s] times). The triangulation splits segments
// where vertices lie on them and where they cross, and a spike that doubles back on itself
// (common in real coastlines) makes two segments overlap: a piece of the mesh may then lie
// on several input segments, and only the total says whether crossing it changes the
// count. Each input segment is walked from end to end along the mesh's constrained edges,
// each step to the neighbour that goes toward the far end most nearly along the segment
// (a crossing's vertex is rounded, so off the line by a rounding).
ConstrainedEdges uses_of_pieces(const Pslg& pslg, const std::vector<int>& uses, const TriMesh& mesh) {
  ConstrainedEdges edges(mesh);
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    const std::uint32_t a = pslg.segments[s].a, b = pslg.segments[s].b;
    const Point target = mesh.points[b];
    std::uint32_t at = a;
    for (std::size_t steps = 0; at != b && steps < mesh.points.size(); ++steps) {
      const Point from = mesh.points[at];
      const double dx = target.x - from.x, dy = target.y - from.y, length2 = dx * dx + dy * dy;
      std::uint32_t best = kNoIndex;
      double best_sine = 1e-6;  // farther off the line than this: no piece of this segment
      for (std::size_t k = edges.start[at]; k < edges.start[at + 1]; ++k) {
        const std::uint32_t x = edges.other[k];
        if (x == b) {
          best = b;
          break;
        }
        const double ex = mesh.points[x].x - from.x, ey = mesh.points[x].y - from.y;
        const double dot = ex * dx + ey * dy, e2 = ex * ex + ey * ey;
        if (dot <= 0.0 || e2 >= length2) continue;  // backward, or past the far end
        const double sine = std::fabs(ex * dy - ey * dx) / std::sqrt(e2 * length2);
        if (sine < best_sine) best_sine = sine, best = x;
      }
      if (best == kNoIndex) break;  // not found: the pieces walked so far keep their counts
      edges.add(at, best, uses[s]);
      at = best;
    }
  }
  return edges;
}

// The hole points of `pslg`, whose segment s the rings use uses[s] times: one inside each
// region, bounded by segments and not reachable from outside them, that the rings enclose
// an even number of times.
std::vector<Point> even_region_points(const Pslg& pslg, const std::vector<int>& uses, TriangulateReport& report) {
  TriangulateOptions options;
  options.convex_hull = true;  // every triangle of the hull, so that parity can be counted from outside
  options.compute_neighbors = true;
  const TriMesh mesh = triangulate(pslg, options, &report);
  const ConstrainedEdges edges = uses_of_pieces(pslg, uses, mesh);
  // Edge i of triangle t: -1 no segment; else 1 when crossing it changes the count (the
  // rings run along it an odd number of times), 0 when not.
  const auto crossing = [&](std::size_t t, int i) {
    const auto& tri = mesh.triangles[t];
    const std::size_t k = edges.find(tri[(i + 1) % 3], tri[(i + 2) % 3]);
    return k == ConstrainedEdges::npos ? -1 : edges.uses[k] % 2;
  };

  // Parity: 0 outside everything; crossing a segment used an odd number of times flips it.
  const std::size_t n = mesh.triangles.size();
  std::vector<int> parity(n, -1);
  std::deque<std::size_t> queue;
  for (std::size_t t = 0; t < n; ++t)
    for (int i = 0; i < 3 && parity[t] < 0; ++i)
      if (mesh.neighbors[t][i] == kNoIndex) {
        parity[t] = crossing(t, i) == 1 ? 1 : 0;
        queue.push_back(t);
      }
  while (!queue.empty()) {
    const std::size_t t = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = mesh.neighbors[t][i];
      if (u == kNoIndex || parity[u] >= 0) continue;
      parity[u] = parity[t] ^ (crossing(t, i) == 1 ? 1 : 0);
      queue.push_back(u);
    }
  }

  // Regions: triangles connected without crossing any segment (what a hole point eats).
  std::vector<std::uint32_t> region(n, kNoIndex);
  std::vector<Point> holes;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (region[seed] != kNoIndex) continue;
    const std::uint32_t id = static_cast<std::uint32_t>(seed);
    std::vector<std::size_t> members{seed};
    region[seed] = id;
    bool open_to_outside = false;  // a hull edge that is no segment: removed as the outside
    for (std::size_t k = 0; k < members.size(); ++k) {
      const std::size_t t = members[k];
      for (int i = 0; i < 3; ++i) {
        const bool segment = crossing(t, i) >= 0;
        const std::uint32_t u = mesh.neighbors[t][i];
        if (u == kNoIndex) open_to_outside = open_to_outside || !segment;
        if (u == kNoIndex || segment || region[u] != kNoIndex) continue;
        region[u] = id;
        members.push_back(u);
      }
    }
    if (open_to_outside || parity[seed] != 0) continue;
    // The largest triangle's centroid, unless rounding put it on an edge: then the next.
    const auto area = [&](std::size_t t) {
      const auto& tri = mesh.triangles[t];
      return orient2d(mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]);
    };
    std::sort(members.begin(), members.end(), [&](std::size_t a, std::size_t b) { return area(a) > area(b); });
    for (const std::size_t t : members) {
      const Point &a = mesh.points[mesh.triangles[t][0]], &b = mesh.points[mesh.triangles[t][1]],
                  &c = mesh.points[mesh.triangles[t][2]];
      const Point g{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
      if (orient2d(a, b, g) > 0 && orient2d(b, c, g) > 0 && orient2d(c, a, g) > 0) {
        holes.push_back(g);
        break;
      }
    }
  }
  return holes;
}

}  // namespace

Pslg pslg_from_rings(const std::string& file, const std::vector<PolygonRing>& rings,
                     std::vector<std::string>* warnings) {
  if (rings.empty()) throw InputError(file, 0, "no polygon in the file");
  Pslg pslg;
  std::unordered_map<PointKey, std::uint32_t, PointKeyHash> vertex_of;
  struct Use {
    std::size_t segment;
    int count;
  };
  std::unordered_map<std::uint64_t, Use> uses;
  std::size_t total = 0;
  for (const PolygonRing& ring : rings) total += ring.points.size();
  vertex_of.reserve(total);  // no rehashing on the way: a third of the time for large files
  uses.reserve(total);
  for (const PolygonRing& ring : rings) {
    std::vector<std::uint32_t> chain;
    for (const Point& p : ring.points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw InputError(file, ring.line, "a coordinate of this ring is not finite");
      const auto [it, added] = vertex_of.emplace(key_of(p), static_cast<std::uint32_t>(pslg.points.size()));
      if (added) pslg.points.push_back(p);
      if (chain.empty() || chain.back() != it->second) chain.push_back(it->second);
    }
    while (chain.size() > 1 && chain.back() == chain.front()) chain.pop_back();
    std::vector<std::uint32_t> distinct = chain;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (distinct.size() < 3)
      throw InputError(file, ring.line,
                       std::string(ring.hole ? "a hole" : "a polygon") +
                           " ring needs at least 3 distinct vertices; this one has " + std::to_string(distinct.size()));
    // A ring that only runs out and back ("0 1, 1 3, 0 1, 1 1": two spikes) encloses nothing.
    std::vector<std::uint64_t> own;
    for (std::size_t i = 0; i < chain.size(); ++i) own.push_back(edge_key(chain[i], chain[(i + 1) % chain.size()]));
    std::sort(own.begin(), own.end());
    own.erase(std::unique(own.begin(), own.end()), own.end());
    if (own.size() < 3)
      throw InputError(file, ring.line,
                       "this ring runs back over itself: it has only " + std::to_string(own.size()) +
                           " distinct segments, and encloses nothing");
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const std::uint32_t a = chain[i], b = chain[(i + 1) % chain.size()];
      const auto [it, added] = uses.emplace(edge_key(a, b), Use{pslg.segments.size(), 0});
      ++it->second.count;
      if (added) pslg.segments.push_back({a, b, ring.hole ? 2 : 1});
    }
  }
  pslg.has_segment_markers = true;
  std::vector<int> use_counts(pslg.segments.size());
  for (const auto& [key, use] : uses) use_counts[use.segment] = use.count;
  TriangulateReport report;
  try {
    pslg.holes = even_region_points(pslg, use_counts, report);
  } catch (const InputError& e) {
    throw InputError(file, 0, e.message());
  }
  // Valid polygons' rings meet at most at vertices; crossing ones are split where they
  // cross (by the triangulation, as for a .poly), and even-odd still says what is a hole.
  if (warnings && report.steiner_vertices)
    warnings->push_back(file + ": the rings cross " + std::to_string(report.steiner_vertices) +
                        " times (a polygon that is not valid): meshed with its segments split there, holes where the "
                        "rings enclose a region an even number of times");
  return pslg;
}

}  // namespace meshstep
