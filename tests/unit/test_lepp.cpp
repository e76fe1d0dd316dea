// The Lepp machinery on its own, on Delaunay triangulations of random and cocircular points:
// the path climbs strictly, the terminal edge is the longest edge of its terminal triangles,
// interior terminal triangles have no angle over 120 degrees, and both data structures
// give the same paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"
#include "triangulate_support.hpp"
#include "meshstep/refine/lepp.hpp"

namespace meshstep {
namespace {

// Rings of points on common circles, and their centers: cocircular quadruples everywhere and
// many edges of equal length, where only the tie-break decides the path.
std::vector<Point> cocircular_points() {
  std::vector<Point> p;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      p.push_back({4.0 * i, 4.0 * j});
      for (const auto& [dx, dy] : {std::pair{1, 0}, {0, 1}, {-1, 0}, {0, -1}}) p.push_back({4.0 * i + dx, 4.0 * j + dy});
    }
  return p;
}

double largest_angle_deg(const Point& a, const Point& b, const Point& c) {
  const auto angle = [](const Point& o, const Point& p, const Point& q) {
    const double ux = p.x - o.x, uy = p.y - o.y, wx = q.x - o.x, wy = q.y - o.y;
    return std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180.0 / std::numbers::pi;
  };
  return std::max({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

double length2(const std::vector<Point>& p, VertexId a, VertexId b) { return quality::squared_distance(p[a], p[b]); }

// Every path of every face of the Delaunay triangulation of `points`, as vertex triples, so
// that two data structures can be compared; and the invariants checked along the way.
template <TriangleMesh Mesh>
std::vector<std::array<VertexId, 3>> check_every_path(const std::vector<Point>& points) {
  Triangulation<Mesh> tri(points, Insertion::flip);
  tri.insert_all();
  const Mesh& mesh = tri.mesh();
  // Faces on the vertex at infinity stand for the outside: hull edges stop a path.
  const auto on_hull = [&](HalfEdge h) { return tri.is_ghost(mesh.face(mesh.twin(h))); };
  std::vector<FaceId> path;
  std::vector<std::array<VertexId, 3>> out;
  std::size_t interior_terminals = 0;
  for (FaceId f = 0; f < mesh.face_capacity(); ++f) {
    if (!mesh.is_live(f) || tri.is_ghost(f)) continue;
    const HalfEdge e = lepp(mesh, points, f, on_hull, path);
    EXPECT_EQ(path.front(), f);
    EXPECT_EQ(mesh.face(e), path[path.size() - (on_hull(e) ? 1 : 2)]);
    // Each step crosses to a longer edge, or an equal one earlier in the tie order.
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const HalfEdge here = longest_edge(mesh, points, path[i]), there = longest_edge(mesh, points, path[i + 1]);
      const double l0 = length2(points, mesh.origin(here), mesh.dest(here));
      const double l1 = length2(points, mesh.origin(there), mesh.dest(there));
      const bool climbs = l1 > l0 || (l1 == l0 && edge_tie_key(mesh.origin(there), mesh.dest(there)) <
                                                      edge_tie_key(mesh.origin(here), mesh.dest(here)));
      EXPECT_TRUE(climbs || (i + 2 == path.size() && there == mesh.twin(here))) << "face " << f << " step " << i;
    }
    if (!on_hull(e)) {
      ++interior_terminals;
      EXPECT_EQ(longest_edge(mesh, points, mesh.face(mesh.twin(e))), mesh.twin(e));
      for (const FaceId g : {mesh.face(e), mesh.face(mesh.twin(e))}) {
        const HalfEdge h = mesh.half_edge(g);
        EXPECT_LE(largest_angle_deg(points[mesh.origin(h)], points[mesh.dest(h)], points[mesh.apex(h)]), 120.0 + 1e-9)
            << "terminal triangle of face " << f;
      }
    } else {
      EXPECT_EQ(longest_edge(mesh, points, path.back()), e);
    }
    for (const FaceId g : path) {
      const HalfEdge h = mesh.half_edge(g);
      std::array<VertexId, 3> v{mesh.origin(h), mesh.dest(h), mesh.apex(h)};
      std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
      out.push_back(v);
    }
    out.push_back({kNone, std::min(mesh.origin(e), mesh.dest(e)), std::max(mesh.origin(e), mesh.dest(e))});
  }
  EXPECT_GT(interior_terminals, 0u);
  return out;
}

// Paths in face order differ between the structures (their face numbering does): compare the
// sets of paths, each a run of triples ending in its terminal-edge marker.
std::vector<std::vector<std::array<VertexId, 3>>> as_sorted_paths(const std::vector<std::array<VertexId, 3>>& flat) {
  std::vector<std::vector<std::array<VertexId, 3>>> paths(1);
  for (const auto& t : flat) {
    paths.back().push_back(t);
    if (t[0] == kNone) paths.emplace_back();
  }
  paths.pop_back();
  std::sort(paths.begin(), paths.end());
  return paths;
}

TEST(Lepp, RandomPointsInvariantsOnBothStructures) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<Point> points = testing::random_unit_points(3000, seed);
    EXPECT_EQ(as_sorted_paths(check_every_path<Tds>(points)), as_sorted_paths(check_every_path<Dcel>(points)));
  }
}

TEST(Lepp, CocircularPointsTiesBrokenTheSameWayEverywhere) {
  const std::vector<Point> points = cocircular_points();
  EXPECT_EQ(as_sorted_paths(check_every_path<Tds>(points)), as_sorted_paths(check_every_path<Dcel>(points)));
}

// A segment stops the path: it ends at the segment with one terminal triangle.
TEST(Lepp, StopsAtAnEdgeTheCallerMarks) {
  // A flat triangle over the edge (0,0)-(10,0), a tall one under it whose longest edges are
  // its sides: the path crosses from the flat one, unless the shared edge is marked.
  const std::vector<Point> points = {{0, 0}, {10, 0}, {5, 1}, {5, -26}};
  Triangulation<Tds> tri(points, Insertion::flip);
  tri.insert_all();
  const Tds& mesh = tri.mesh();
  FaceId thin = kNone;
  for (FaceId f = 0; f < mesh.face_capacity(); ++f) {
    if (!mesh.is_live(f) || tri.is_ghost(f)) continue;
    const HalfEdge h = mesh.half_edge(f);
    for (const VertexId v : {mesh.origin(h), mesh.dest(h), mesh.apex(h)})
      if (v == 2) thin = f;
  }
  ASSERT_NE(thin, kNone);
  std::vector<FaceId> path;
  const auto on_hull = [&](HalfEdge h) { return tri.is_ghost(mesh.face(mesh.twin(h))); };
  const HalfEdge free_end = lepp(mesh, points, thin, on_hull, path);
  EXPECT_EQ(path.size(), 2u);
  EXPECT_TRUE(on_hull(free_end)) << "ends on a side of the tall triangle, on the hull";
  EXPECT_NE(mesh.face(free_end), thin);
  const auto on_hull_or_marked = [&](HalfEdge h) {
    return on_hull(h) || edge_tie_key(mesh.origin(h), mesh.dest(h)) == edge_tie_key(0, 1);
  };
  const HalfEdge stopped = lepp(mesh, points, thin, on_hull_or_marked, path);
  EXPECT_EQ(path.size(), 1u);
  EXPECT_EQ(mesh.face(stopped), thin);
}

}  // namespace
}  // namespace meshstep
