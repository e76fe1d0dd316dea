// Vertex removal on its own (delaunay/vertex_removal.hpp), on Delaunay triangulations of
// random and cocircular points: after each removal the mesh is exactly the Delaunay
// triangulation of the remaining points (under the same tie-break), the plan is what the
// mesh holds, both data structures agree, and vertices that are not free are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <vector>

#include "mesh_validate.hpp"
#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/delaunay/vertex_removal.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

using PointTriangle = std::array<std::pair<double, double>, 3>;

// A grid with the centres of its cells: four cocircular points round every centre, and
// every centre on the diagonals of its cell.
std::vector<Point> grid_points() {
  std::vector<Point> p;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      p.push_back({2.0 * i, 2.0 * j});
      if (i < 7 && j < 7) p.push_back({2.0 * i + 1, 2.0 * j + 1});
    }
  return p;
}

// The finite faces by their corners' coordinates, each rotated to start at its smallest
// corner; sorted. Independent of vertex ids, so two triangulations of one point set built
// differently compare equal when they hold the same triangles.
template <TriangleMesh Mesh>
std::vector<PointTriangle> triangles_by_position(const Triangulation<Mesh>& tri) {
  std::vector<PointTriangle> out;
  const Mesh& m = tri.mesh();
  for (FaceId f = 0; f < m.face_capacity(); ++f) {
    if (!m.is_live(f) || tri.is_ghost(f)) continue;
    const HalfEdge h = m.half_edge(f);
    PointTriangle t;
    const VertexId v[3] = {m.origin(h), m.dest(h), m.apex(h)};
    for (int i = 0; i < 3; ++i) t[i] = {tri.point(v[i]).x, tri.point(v[i]).y};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <TriangleMesh Mesh>
bool holds(const Triangulation<Mesh>& tri, const std::array<VertexId, 3>& t) {
  const HalfEdge h = tri.find_edge(t[0], t[1]);
  return h != kNone && tri.mesh().apex(h) == t[2];
}

// Removes vertices in a random order from the Delaunay triangulation of `points`, checking
// after each that the mesh is the Delaunay triangulation of what remains. Returns the
// final triangles and the number removed.
template <TriangleMesh Mesh>
std::pair<std::vector<PointTriangle>, std::size_t> remove_many(const std::vector<Point>& points, std::uint64_t seed,
                                                               std::size_t check_every) {
  Triangulation<Mesh> tri(points, Insertion::flip);
  tri.insert_all();
  VertexRemover<Mesh, replay::NullRecorder> remover(tri);
  std::vector<VertexId> order(points.size());
  for (VertexId v = 0; v < order.size(); ++v) order[v] = v;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(seed));
  std::vector<std::uint8_t> gone(points.size(), 0);
  std::size_t removed = 0, refused = 0;
  for (const VertexId v : order) {
    if (removed >= points.size() / 2) break;
    const HalfEdge out = tri.mesh().vertex_half_edge(v);
    if (!remover.plan(out)) {
      ++refused;
      continue;
    }
    const std::size_t degree = remover.old_triangles().size();
    const auto planned = remover.new_triangles();
    EXPECT_EQ(planned.size(), degree - 2);
    remover.apply();
    gone[v] = 1;
    ++removed;
    EXPECT_EQ(tri.mesh().vertex_half_edge(v), kNone);
    for (const auto& t : planned) EXPECT_TRUE(holds(tri, t)) << "planned triangle missing after removing " << v;
    if (removed % check_every != 0) continue;
    const auto problems = validate_connectivity(tri.mesh());
    EXPECT_TRUE(problems.empty()) << problems.front();
    std::vector<Point> rest;
    for (VertexId w = 0; w < points.size(); ++w)
      if (!gone[w]) rest.push_back(points[w]);
    Triangulation<Mesh> fresh(rest, Insertion::flip);
    fresh.insert_all();
    EXPECT_EQ(triangles_by_position(tri), triangles_by_position(fresh)) << "after removing " << removed;
  }
  EXPECT_GT(removed, points.size() / 4);
  EXPECT_GT(refused, 0u);  // the hull's vertices at least
  return {triangles_by_position(tri), removed};
}

TEST(VertexRemoval, RandomPointsLeaveTheDelaunayTriangulationOfTheRest) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<Point> points = testing::random_unit_points(400, seed);
    const auto tds = remove_many<Tds>(points, seed, 20);
    const auto dcel = remove_many<Dcel>(points, seed, 50);
    EXPECT_EQ(tds, dcel);
  }
}

TEST(VertexRemoval, CocircularPointsFollowTheTieBreak) {
  const std::vector<Point> points = grid_points();
  const auto tds = remove_many<Tds>(points, 7, 5);
  const auto dcel = remove_many<Dcel>(points, 7, 5);
  EXPECT_EQ(tds, dcel);
}

TEST(VertexRemoval, VerticesThatAreNotFreeAreRefused) {
  // A square and its centre: the corners are on the hull (a ghost face round each), and
  // the centre is free until one of its edges is constrained.
  Triangulation<Tds> tri({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0.8}}, Insertion::flip);
  tri.insert_all();
  VertexRemover<Tds, replay::NullRecorder> remover(tri);
  for (VertexId corner = 0; corner < 4; ++corner) EXPECT_FALSE(remover.plan(tri.mesh().vertex_half_edge(corner)));
  ASSERT_TRUE(remover.plan(tri.mesh().vertex_half_edge(4)));
  EXPECT_EQ(remover.old_triangles().size(), 4u);
  EXPECT_EQ(remover.new_triangles().size(), 2u);
  tri.set_constrained(tri.find_edge(4, 0), true, 1);
  EXPECT_FALSE(remover.plan(tri.mesh().vertex_half_edge(4)));
}

TEST(VertexRemoval, AVertexOnAPlannedEdgeGoesThroughAFlatTriangle) {
  // The centre of a square lies on both diagonals: the plan takes one, and the flip that
  // makes it leaves the centre on it, in a flat triangle that the merge removes.
  for (const Point centre : {Point{1, 1}, Point{1, 0.5}}) {
    Triangulation<Dcel> tri({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {4, 1}, centre}, Insertion::flip);
    tri.insert_all();
    VertexRemover<Dcel, replay::NullRecorder> remover(tri);
    ASSERT_TRUE(remover.plan(tri.mesh().vertex_half_edge(5)));
    const auto planned = remover.new_triangles();
    remover.apply();
    for (const auto& t : planned) EXPECT_TRUE(holds(tri, t));
    Triangulation<Dcel> fresh({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {4, 1}}, Insertion::flip);
    fresh.insert_all();
    EXPECT_EQ(triangles_by_position(tri), triangles_by_position(fresh));
  }
}

}  // namespace
}  // namespace meshstep
