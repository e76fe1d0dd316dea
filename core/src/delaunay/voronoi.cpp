// The Voronoi diagram as the dual of the mesh (delaunay/voronoi.hpp), and its files.
#include "meshstep/delaunay/voronoi.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include "io/atomic_writer.hpp"

namespace meshstep {

namespace {

// The circumcenter of a b c, computed from a so that the subtraction cancels the large common
// part of coordinates far from the origin. A degenerate (collinear) triangle has none; the
// mesh has no such triangle, but a damaged one would give inf or nan, written as such.
Point circumcenter(const Point& a, const Point& b, const Point& c) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double d = 2.0 * (bx * cy - by * cx);
  return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

}  // namespace

VoronoiDiagram voronoi_of(const TriMesh& mesh) { return voronoi_of(mesh.points, mesh.triangles); }

VoronoiDiagram voronoi_of(std::span<const Point> points, std::span<const std::array<std::uint32_t, 3>> triangles) {
  VoronoiDiagram out;
  out.vertices.reserve(triangles.size());
  for (const auto& t : triangles) out.vertices.push_back(circumcenter(points[t[0]], points[t[1]], points[t[2]]));
  // Every triangle's edges, keyed by their ends; an edge met twice is interior.
  struct Side {
    std::uint32_t lo, hi, triangle;
    std::uint32_t from, to;  // the edge as the (counterclockwise) triangle runs it
  };
  std::vector<Side> sides;
  sides.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = triangles[t][i], v = triangles[t][(i + 1) % 3];
      sides.push_back({std::min(u, v), std::max(u, v), t, u, v});
    }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
  });
  for (std::size_t i = 0; i < sides.size();) {
    const Side& s = sides[i];
    if (i + 1 < sides.size() && sides[i + 1].lo == s.lo && sides[i + 1].hi == s.hi) {
      out.edges.push_back({s.triangle, sides[i + 1].triangle, {}, s.from, s.to});
      i += 2;
      continue;
    }
    // A boundary edge: the mesh is on its left (counterclockwise triangles), so the outward
    // normal is the edge turned clockwise.
    const Point &p = points[s.from], &q = points[s.to];
    out.edges.push_back({s.triangle, kNoIndex, {q.y - p.y, p.x - q.x}, s.from, s.to});
    i += 1;
  }
  return out;
}

void write_voronoi(const std::string& prefix, const VoronoiDiagram& diagram, int first_index) {
  io::detail::AtomicWriter node(prefix + ".v.node");
  // Triangle's .node header: vertices, dimension, attributes, boundary markers.
  node.integer(static_cast<std::int64_t>(diagram.vertices.size()));
  node.text("  2  0  0\n");
  for (std::size_t i = 0; i < diagram.vertices.size(); ++i) {
    node.integer(static_cast<std::int64_t>(i) + first_index);
    node.ch(' ');
    node.real(diagram.vertices[i].x);
    node.ch(' ');
    node.real(diagram.vertices[i].y);
    node.ch('\n');
  }
  node.text("# Voronoi vertices: vertex k is the circumcenter of triangle k of the .ele\n");

  io::detail::AtomicWriter edge(prefix + ".v.edge");
  edge.integer(static_cast<std::int64_t>(diagram.edges.size()));
  edge.text("  0\n");
  for (std::size_t i = 0; i < diagram.edges.size(); ++i) {
    const VoronoiDiagram::Edge& e = diagram.edges[i];
    edge.integer(static_cast<std::int64_t>(i) + first_index);
    edge.ch(' ');
    edge.integer(static_cast<std::int64_t>(e.a) + first_index);
    if (e.b == kNoIndex) {  // a ray: -1, then its direction
      edge.text(" -1 ");
      edge.real(e.direction.x);
      edge.ch(' ');
      edge.real(e.direction.y);
    } else {
      edge.ch(' ');
      edge.integer(static_cast<std::int64_t>(e.b) + first_index);
    }
    edge.ch('\n');
  }
  edge.text("# Voronoi edges; an edge ending in -1 is a ray, followed by its direction\n");
  node.commit();
  edge.commit();
}

}  // namespace meshstep
