// The Voronoi layer: the dual of the mesh in the scene, drawn as a textbook draws it beside
// a Delaunay triangulation. A Voronoi vertex at every triangle's circumcenter, an edge
// between the circumcenters of two triangles that share an edge, a ray from a triangle on
// the convex hull outwards across its hull edge, and the sites (the mesh's vertices) as dots.
// Everything is cut to a box a little larger than the mesh: the circumcenter of a nearly
// flat hull triangle may lie a thousand times the mesh away, and a ray has no end.
//
// A boundary edge that is not on the convex hull (a hole's, a concave outline's) gets no
// ray: its dual would cross the hole or the outside and meet other rays, which says nothing
// about the diagram of the domain. Such a mesh's dual is not the points' Voronoi diagram
// anyway (delaunay/voronoi.hpp); inside the domain it is what Triangle's -v writes.
#include <algorithm>
#include <cmath>
#include <utility>

#include "meshstep/delaunay/voronoi.hpp"
#include "meshstep/geometry/predicates.hpp"
#include "parts.hpp"
#include "style.hpp"

namespace meshstep::scene::detail {

namespace {

// The box grows by this share of the mesh's larger side on each side: room for the rays to
// be seen leaving the hull.
constexpr double kMargin = 0.2;

using Hop = std::pair<std::uint32_t, std::uint32_t>;

// The convex hull's edges as consecutive vertices counterclockwise, points on a hull edge
// kept as hull vertices (so that a boundary edge between two collinear hull points counts).
// Andrew's monotone chain with the exact orientation test.
std::vector<Hop> hull_hops(std::span<const Point> points, std::vector<std::uint32_t> used) {
  std::sort(used.begin(), used.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::pair(points[a].x, points[a].y) < std::pair(points[b].x, points[b].y);
  });
  if (used.size() < 3) return {};
  std::vector<std::uint32_t> chain;
  const auto walk = [&](auto first, auto last) {
    const std::size_t base = chain.size();
    for (auto it = first; it != last; ++it) {
      while (chain.size() >= base + 2 && orient2d(points[chain[chain.size() - 2]], points[chain.back()], points[*it]) < 0)
        chain.pop_back();
      chain.push_back(*it);
    }
    chain.pop_back();  // the other chain's first vertex
  };
  walk(used.begin(), used.end());
  walk(used.rbegin(), used.rend());
  std::vector<Hop> hops;
  for (std::size_t i = 0; i < chain.size(); ++i) hops.push_back({chain[i], chain[(i + 1) % chain.size()]});
  std::sort(hops.begin(), hops.end());
  return hops;
}

// Cuts the segment p + t (q - p), t in [t0, t1], to the box (Liang-Barsky). False when
// nothing of it is inside.
bool clip(const BBox& box, Point p, Point d, double t0, double t1, Point& a, Point& b) {
  const double p_[4] = {-d.x, d.x, -d.y, d.y};
  const double q_[4] = {p.x - box.lo.x, box.hi.x - p.x, p.y - box.lo.y, box.hi.y - p.y};
  for (int i = 0; i < 4; ++i) {
    if (p_[i] == 0.0) {
      if (q_[i] < 0.0) return false;
      continue;
    }
    const double r = q_[i] / p_[i];
    if (p_[i] < 0.0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
    if (t0 > t1) return false;
  }
  if (!std::isfinite(t1)) return false;
  a = {p.x + t0 * d.x, p.y + t0 * d.y};
  b = {p.x + t1 * d.x, p.y + t1 * d.y};
  return true;
}

bool finite(const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

bool inside(const BBox& box, const Point& p) {
  return p.x >= box.lo.x && p.x <= box.hi.x && p.y >= box.lo.y && p.y <= box.hi.y;
}

Shape& add_shape(Scene& scene, ShapeKind kind, const char* role, const char* label) {
  Shape& s = scene.shapes.emplace_back();
  s.layer = Layer::voronoi;
  s.kind = kind;
  s.role = role;
  s.label = label;
  return s;
}

}  // namespace

void add_voronoi(Scene& scene, const SceneOptions& options) {
  const MeshLayer& mesh = scene.mesh;
  if (mesh.triangles.empty()) return;
  std::vector<std::uint32_t> used;
  used.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) used.insert(used.end(), t.begin(), t.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  BBox box;
  for (const std::uint32_t v : used) box.add(mesh.points[v]);
  const double grow = kMargin * std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
  const BBox limit{{box.lo.x - grow, box.lo.y - grow}, {box.hi.x + grow, box.hi.y + grow}};

  const VoronoiDiagram diagram = voronoi_of(mesh.points, mesh.triangles);
  const std::vector<Hop> hull = hull_hops(mesh.points, used);
  const BaseStyle& style = base_style(scene.theme);

  Shape& edges = add_shape(scene, ShapeKind::lines, "voronoi_edges", "Voronoi edges: between the circumcenters of neighbours");
  edges.color = style.voronoi;
  edges.width_px = style.voronoi_width_px;
  std::vector<Point> rays;
  for (const VoronoiDiagram::Edge& e : diagram.edges) {
    const Point& c = diagram.vertices[e.a];
    if (!finite(c)) continue;
    Point a, b;
    if (e.b != kNoIndex) {
      const Point& other = diagram.vertices[e.b];
      if (!finite(other) || other == c) continue;  // cocircular neighbours share their circumcenter
      if (clip(limit, c, {other.x - c.x, other.y - c.y}, 0.0, 1.0, a, b)) edges.points.insert(edges.points.end(), {a, b});
    } else if (std::binary_search(hull.begin(), hull.end(), Hop{e.from, e.to})) {
      if (clip(limit, c, e.direction, 0.0, INFINITY, a, b) && a != b) rays.insert(rays.end(), {a, b});
    }
  }
  Shape& ray_shape = add_shape(scene, ShapeKind::lines, "voronoi_rays", "Voronoi rays: out of the hull's triangles");
  ray_shape.color = style.voronoi;
  ray_shape.width_px = style.voronoi_width_px;
  ray_shape.points = std::move(rays);

  if (mesh.triangles.size() <= options.max_vertex_markers) {
    Shape& centers = add_shape(scene, ShapeKind::markers, "voronoi_vertices", "Voronoi vertices: the circumcenters");
    centers.color = style.voronoi;
    centers.fill = style.voronoi;
    centers.width_px = 1.0f;
    centers.marker_px = 5.0f;
    for (const Point& c : diagram.vertices)
      if (finite(c) && inside(limit, c)) centers.points.push_back(c);
  }
  if (used.size() <= options.max_vertex_markers) {
    Shape& sites = add_shape(scene, ShapeKind::markers, "voronoi_sites", "sites: the mesh's vertices");
    sites.color = style.background;
    sites.fill = style.voronoi_site;
    sites.width_px = 1.0f;
    sites.marker_px = 7.0f;
    for (const std::uint32_t v : used) sites.points.push_back(mesh.points[v]);
  }
  // Empty shapes (a mesh whose every edge is cut away) are dropped: tests look roles up.
  std::erase_if(scene.shapes, [](const Shape& s) { return s.layer == Layer::voronoi && s.points.empty(); });
  // The triangulation steps back, as in a textbook's figure of the two.
  scene.mesh.edge_color = style.faint_edge;
}

}  // namespace meshstep::scene::detail
