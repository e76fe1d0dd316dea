#include "inspector.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <tuple>
#include <unordered_map>

#include "meshstep/geometry/predicates.hpp"
#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/refine/quality.hpp"

namespace meshstep::viewer {

namespace {

double squared(double x) { return x * x; }
double distance2(const Point& p, const Point& q) { return squared(p.x - q.x) + squared(p.y - q.y); }

bool valid(const scene::MeshLayer& mesh, const std::array<std::uint32_t, 3>& t) {
  return t[0] < mesh.points.size() && t[1] < mesh.points.size() && t[2] < mesh.points.size();
}

// Edge i of a triangle runs from its vertex i to vertex i + 1. With heights, edges are
// measured in 3D and ties go to the smaller vertex ids, both as Lepp-surface has them
// (terrain/tin_builder.hpp), so that the path is the one the run followed.
int longest_edge(const scene::MeshLayer& mesh, const std::array<std::uint32_t, 3>& t, std::span<const double> heights) {
  int best = 0;
  std::array<double, 3> longest{-1.0, 0.0, 0.0};
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t u = t[i], w = t[(i + 1) % 3];
    const Point &p = mesh.points[u], &q = mesh.points[w];
    std::array<double, 3> key{distance2(p, q), 0.0, 0.0};
    if (u < heights.size() && w < heights.size()) {
      const double dz = heights[u] - heights[w];
      key = {(p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) + dz * dz, -static_cast<double>(std::min(u, w)),
             -static_cast<double>(std::max(u, w))};
    }
    // In the plane, ties go to the first edge of the triangle.
    if (key > longest) best = i, longest = key;
  }
  return best;
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

}  // namespace

Picked pick(const scene::MeshLayer& mesh, Point at, double radius) {
  Picked vertex, triangle;
  double nearest = radius * radius;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    if (!valid(mesh, v)) continue;
    for (const std::uint32_t i : v)
      if (const double d = distance2(mesh.points[i], at); d <= nearest) {
        nearest = d;
        vertex = {Picked::Kind::vertex, i};
      }
    if (triangle.kind == Picked::Kind::none) {
      const Point &a = mesh.points[v[0]], &b = mesh.points[v[1]], &c = mesh.points[v[2]];
      if (orient2d(a, b, at) >= 0 && orient2d(b, c, at) >= 0 && orient2d(c, a, at) >= 0)
        triangle = {Picked::Kind::triangle, t};
    }
  }
  return vertex.kind != Picked::Kind::none ? vertex : triangle;
}

Picked pick_front(const scene::MeshLayer& shown, Point at, double radius) {
  for (std::size_t k = shown.triangles.size(); k-- > 0;) {
    const auto& v = shown.triangles[k];
    if (!valid(shown, v)) continue;
    const Point &a = shown.points[v[0]], &b = shown.points[v[1]], &c = shown.points[v[2]];
    if (!(orient2d(a, b, at) >= 0 && orient2d(b, c, at) >= 0 && orient2d(c, a, at) >= 0)) continue;
    Picked picked{Picked::Kind::triangle, static_cast<std::uint32_t>(k)};
    double nearest = radius * radius;
    for (const std::uint32_t i : v)
      if (const double d = distance2(shown.points[i], at); d <= nearest) {
        nearest = d;
        picked = {Picked::Kind::vertex, i};
      }
    return picked;
  }
  return {};
}

std::uint32_t find_triangle(const scene::MeshLayer& mesh, std::array<std::uint32_t, 3> vertices) {
  std::sort(vertices.begin(), vertices.end());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    auto v = mesh.triangles[t];
    std::sort(v.begin(), v.end());
    if (v == vertices) return t;
  }
  return kNoIndex;
}

namespace {

// Two points as one key, the smaller first (an edge's key whichever way it runs).
std::array<std::uint64_t, 4> point_pair_key(const Point& p, const Point& q) {
  std::array<std::uint64_t, 4> k{std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y),
                                 std::bit_cast<std::uint64_t>(q.x), std::bit_cast<std::uint64_t>(q.y)};
  if (std::tie(k[2], k[3]) < std::tie(k[0], k[1])) std::swap(k[0], k[2]), std::swap(k[1], k[3]);
  return k;
}

double distance2_to_segment(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  const double t = l2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
  return distance2(p, {a.x + t * dx, a.y + t * dy});
}

}  // namespace

std::vector<MeshEdge> constrained_edges(const scene::Scene& scene) {
  // The shape has coordinates only: its edges are found again among the triangles' edges
  // by their points' exact coordinates (the scene copies them from the mesh's points).
  std::vector<std::array<std::uint64_t, 4>> keys;
  for (const scene::Shape& shape : scene.shapes)
    if (shape.role == "segments")
      for (std::size_t i = 0; i + 1 < shape.points.size(); i += 2)
        keys.push_back(point_pair_key(shape.points[i], shape.points[i + 1]));
  std::sort(keys.begin(), keys.end());
  std::vector<MeshEdge> edges;
  if (keys.empty()) return edges;
  const scene::MeshLayer& mesh = scene.mesh;
  for (const auto& t : mesh.triangles) {
    if (!valid(mesh, t)) continue;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      if (std::binary_search(keys.begin(), keys.end(), point_pair_key(mesh.points[a], mesh.points[b])))
        edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

Picked pick(const scene::MeshLayer& mesh, std::span<const MeshEdge> edges, Point at, double vertex_radius,
            double edge_radius) {
  const Picked vertex_or_triangle = pick(mesh, at, vertex_radius);
  if (vertex_or_triangle.kind == Picked::Kind::vertex) return vertex_or_triangle;
  Picked edge;
  double nearest = edge_radius * edge_radius;
  for (const MeshEdge& e : edges) {
    if (e[0] >= mesh.points.size() || e[1] >= mesh.points.size()) continue;
    if (const double d = distance2_to_segment(at, mesh.points[e[0]], mesh.points[e[1]]); d <= nearest) {
      nearest = d;
      edge = {Picked::Kind::segment, e[0], e[1]};
    }
  }
  return edge.kind != Picked::Kind::none ? edge : vertex_or_triangle;
}

TriangleFacts triangle_facts(const scene::MeshLayer& mesh, std::uint32_t triangle) {
  TriangleFacts f;
  if (triangle >= mesh.triangles.size() || !valid(mesh, mesh.triangles[triangle])) return f;
  f.vertices = mesh.triangles[triangle];
  const Point* p[3] = {&mesh.points[f.vertices[0]], &mesh.points[f.vertices[1]], &mesh.points[f.vertices[2]]};
  for (int i = 0; i < 3; ++i) {
    const Point &o = *p[i], &u = *p[(i + 1) % 3], &w = *p[(i + 2) % 3];
    const double ux = u.x - o.x, uy = u.y - o.y, wx = w.x - o.x, wy = w.y - o.y;
    f.angles[static_cast<std::size_t>(i)] = std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180.0 / M_PI;
  }
  f.area = 0.5 * std::abs((p[1]->x - p[0]->x) * (p[2]->y - p[0]->y) - (p[1]->y - p[0]->y) * (p[2]->x - p[0]->x));
  f.min_angle = *std::min_element(f.angles.begin(), f.angles.end());
  return f;
}

LeppPath lepp_path(const scene::MeshLayer& mesh, std::uint32_t triangle, std::span<const double> heights) {
  LeppPath path;
  if (triangle >= mesh.triangles.size() || !valid(mesh, mesh.triangles[triangle])) return path;
  // Each edge's triangles (two at most in a valid mesh).
  std::unordered_map<std::uint64_t, std::array<std::uint32_t, 2>> edges;
  edges.reserve(mesh.triangles.size() * 2);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    if (!valid(mesh, v)) continue;
    for (int i = 0; i < 3; ++i) {
      auto [it, fresh] = edges.try_emplace(edge_key(v[i], v[(i + 1) % 3]), std::array<std::uint32_t, 2>{t, kNoIndex});
      if (!fresh) it->second[1] = t;
    }
  }
  std::uint32_t t = triangle;
  for (std::size_t guard = 0; guard <= mesh.triangles.size(); ++guard) {
    path.triangles.push_back(t);
    const auto& v = mesh.triangles[t];
    const int e = longest_edge(mesh, v, heights);
    path.a = v[static_cast<std::size_t>(e)];
    path.b = v[static_cast<std::size_t>((e + 1) % 3)];
    const auto& across = edges.at(edge_key(path.a, path.b));
    const std::uint32_t next = across[0] == t ? across[1] : across[0];
    if (next == kNoIndex) {
      path.boundary = true;
      return path;
    }
    const auto& w = mesh.triangles[next];
    const int f = longest_edge(mesh, w, heights);
    if (edge_key(w[static_cast<std::size_t>(f)], w[static_cast<std::size_t>((f + 1) % 3)]) == edge_key(path.a, path.b)) {
      path.triangles.push_back(next);  // the terminal pair
      return path;
    }
    t = next;
  }
  return path;  // longest edges strictly grow along a path: not reached
}

}  // namespace meshstep::viewer
