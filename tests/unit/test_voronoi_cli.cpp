// meshstep triangulate --voronoi: Triangle's .v.node and .v.edge, read back and held to
// what a Voronoi diagram is as the Delaunay triangulation's dual: vertex k is equidistant
// from the three corners of triangle k, a finite edge joins the circumcenters of two
// triangles that share an edge, and a ray leaves a hull edge's triangle perpendicular to
// that edge, outward.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/io/triangle_io.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using testing::CommandResult;
using testing::run_meshstep;
using testing::TempDir;

// The numbers of a Triangle file, line by line, comments and blank lines left out.
std::vector<std::vector<std::string>> records(const std::string& path) {
  std::vector<std::vector<std::string>> out;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::vector<std::string> r;
    for (std::string w; words >> w;) r.push_back(w);
    if (!r.empty()) out.push_back(r);
  }
  return out;
}

double distance(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

struct Readback {
  TriMesh mesh;
  std::vector<Point> vertices;
  struct Edge {
    long a, b;
    Point direction;
  };
  std::vector<Edge> edges;
};

Readback triangulate_with_voronoi(const TempDir& dir, const std::string& input) {
  Readback r;
  const CommandResult run =
      run_meshstep("triangulate " + input + " --voronoi -o " + dir.file("out") + " -q", dir.path());
  EXPECT_EQ(run.status, 0) << run.err;
  r.mesh = io::read_mesh(dir.file("out"));
  const int first = r.mesh.first_index;
  const auto node = records(dir.file("out.v.node"));
  const auto edge = records(dir.file("out.v.edge"));
  EXPECT_FALSE(node.empty());
  EXPECT_FALSE(edge.empty());
  if (node.empty() || edge.empty()) return r;
  EXPECT_EQ(node[0][1], "2");
  EXPECT_EQ(std::stoul(node[0][0]), node.size() - 1);
  EXPECT_EQ(std::stoul(edge[0][0]), edge.size() - 1);
  for (std::size_t i = 1; i < node.size(); ++i) {
    EXPECT_EQ(std::stol(node[i][0]), static_cast<long>(i - 1) + first);
    r.vertices.push_back({std::stod(node[i][1]), std::stod(node[i][2])});
  }
  for (std::size_t i = 1; i < edge.size(); ++i) {
    const auto& e = edge[i];
    Readback::Edge x{std::stol(e[1]) - first, std::stol(e[2]), {}};
    if (x.b == -1) {
      EXPECT_EQ(e.size(), 5u) << "a ray has a direction";
      x.direction = {std::stod(e[3]), std::stod(e[4])};
    } else {
      x.b -= first;
    }
    r.edges.push_back(x);
  }
  return r;
}

void check_dual(const Readback& r) {
  const TriMesh& m = r.mesh;
  ASSERT_EQ(r.vertices.size(), m.triangles.size()) << "one Voronoi vertex per triangle";
  // Vertex k: the circumcenter of triangle k.
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Point &a = m.points[m.triangles[t][0]], &b = m.points[m.triangles[t][1]], &c = m.points[m.triangles[t][2]];
    const double ra = distance(r.vertices[t], a), rb = distance(r.vertices[t], b), rc = distance(r.vertices[t], c);
    EXPECT_NEAR(ra, rb, 1e-9 * (1.0 + ra)) << "triangle " << t;
    EXPECT_NEAR(ra, rc, 1e-9 * (1.0 + ra)) << "triangle " << t;
  }
  // The mesh's edges and the triangles beside them.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> beside;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = m.triangles[t][i], v = m.triangles[t][(i + 1) % 3];
      beside[{std::min(u, v), std::max(u, v)}].push_back(t);
    }
  ASSERT_EQ(r.edges.size(), beside.size()) << "one Voronoi edge per mesh edge";
  std::size_t rays = 0, finite = 0;
  for (const Readback::Edge& e : r.edges) {
    ASSERT_GE(e.a, 0);
    ASSERT_LT(static_cast<std::size_t>(e.a), m.triangles.size());
    const auto& t = m.triangles[e.a];
    if (e.b >= 0) {  // two triangles that share an edge
      ++finite;
      ASSERT_LT(static_cast<std::size_t>(e.b), m.triangles.size());
      int shared = 0;
      for (const auto x : t) shared += std::count(m.triangles[e.b].begin(), m.triangles[e.b].end(), x) > 0;
      EXPECT_EQ(shared, 2) << "triangles " << e.a << " and " << e.b;
      continue;
    }
    // A ray: from a triangle with a hull edge, perpendicular to it, away from the third corner.
    ++rays;
    bool found = false;
    for (int i = 0; i < 3 && !found; ++i) {
      const std::uint32_t u = t[i], v = t[(i + 1) % 3], w = t[(i + 2) % 3];
      if (beside[{std::min(u, v), std::max(u, v)}].size() != 1) continue;
      const Point &p = m.points[u], &q = m.points[v], &apex = m.points[w];
      const double along = e.direction.x * (q.x - p.x) + e.direction.y * (q.y - p.y);
      if (std::abs(along) > 1e-12 * (1.0 + distance(p, q) * std::hypot(e.direction.x, e.direction.y))) continue;
      const Point mid{(p.x + q.x) / 2, (p.y + q.y) / 2};
      EXPECT_LT(e.direction.x * (apex.x - mid.x) + e.direction.y * (apex.y - mid.y), 0.0) << "outward";
      found = true;
    }
    EXPECT_TRUE(found) << "the ray from triangle " << e.a << " is perpendicular to none of its hull edges";
  }
  std::size_t hull = 0;
  for (const auto& [edge, ts] : beside) hull += ts.size() == 1;
  EXPECT_EQ(rays, hull);
  EXPECT_EQ(finite, beside.size() - hull);
}

TEST(VoronoiCli, RandomPointsGiveTheDualOfTheirDelaunayTriangulation) {
  TempDir dir;
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  std::ostringstream node;
  node << "200 2 0 0\n";
  for (int i = 1; i <= 200; ++i) node << i << ' ' << u(rng) << ' ' << u(rng) << '\n';
  const Readback r = triangulate_with_voronoi(dir, dir.write("points.node", node.str()));
  ASSERT_FALSE(r.mesh.triangles.empty());
  EXPECT_EQ(r.mesh.first_index, 1);
  check_dual(r);
}

TEST(VoronoiCli, APslgWithAHoleGivesItsMeshsDual) {
  TempDir dir;
  check_dual(triangulate_with_voronoi(dir, std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly"));
}

TEST(VoronoiCli, NoVoronoiFilesUnlessAsked) {
  TempDir dir;
  const CommandResult run = run_meshstep(
      "triangulate " + std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly -o " + dir.file("plain") + " -q", dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("plain.v.node")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("plain.v.edge")));
}

}  // namespace
}  // namespace meshstep
