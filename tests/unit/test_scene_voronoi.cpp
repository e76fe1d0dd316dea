// The Voronoi layer (issue 29, item 6): the dual of the mesh at the cursor, drawn from a
// recorded run's last moment and held to the diagram `meshstep triangulate --voronoi`
// writes for the same input (.v.node, .v.edge, read back here as numbers), and to
// circumcenters computed here. The layer is off unless asked for, and switching it on
// lightens the Delaunay edges under it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/build.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep::scene {
namespace {

std::vector<std::vector<double>> rows_of(const std::string& path) {
  std::vector<std::vector<double>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::vector<double> row;
    for (double v; words >> v;) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

double distance(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

bool near(const Point& a, const Point& b, double scale) { return distance(a, b) <= 1e-9 * scale; }

// The diagram Triangle's -v files describe: vertices, finite edges (two vertices), rays (a
// vertex and a direction).
struct Files {
  std::vector<Point> vertices;
  std::vector<std::pair<Point, Point>> edges;
  std::vector<std::pair<Point, Point>> rays;  // start, direction
};

Files read_voronoi(const std::string& prefix) {
  Files f;
  const auto node = rows_of(prefix + ".v.node"), edge = rows_of(prefix + ".v.edge");
  const int first = node.size() > 1 ? static_cast<int>(node[1][0]) : 0;
  for (std::size_t i = 1; i < node.size(); ++i) f.vertices.push_back({node[i][1], node[i][2]});
  for (std::size_t i = 1; i < edge.size(); ++i) {
    const Point a = f.vertices.at(static_cast<std::size_t>(edge[i][1]) - first);
    if (edge[i][2] == -1)
      f.rays.push_back({a, {edge[i][3], edge[i][4]}});
    else
      f.edges.push_back({a, f.vertices.at(static_cast<std::size_t>(edge[i][2]) - first)});
  }
  return f;
}

// A run of `meshstep triangulate INPUT --voronoi --record`, its scene at the end with the
// Voronoi layer, and the files.
struct VoronoiRun {
  Scene scene;
  Files files;
  BBox points;  // of the mesh's vertices
  double scale = 1.0;
};

VoronoiRun run_voronoi(const testing::TempDir& dir, const std::string& input) {
  const testing::CommandResult r = testing::run_meshstep(
      "triangulate " + input + " --voronoi -o " + dir.file("out") + " --record " + dir.file("run.mslog") + " -q",
      dir.path());
  EXPECT_EQ(r.status, 0) << r.err;
  VoronoiRun out;
  out.files = read_voronoi(dir.file("out"));
  const replay::LogReader log(dir.file("run.mslog"));
  replay::Replay cursor(log);
  cursor.seek_event(log.event_count());
  SceneOptions options;
  options.layers.set(Layer::voronoi);
  out.scene = build_scene(cursor, options);
  for (const auto& t : out.scene.mesh.triangles)
    for (const std::uint32_t v : t) out.points.add(out.scene.mesh.points[v]);
  out.scale = std::max(out.points.hi.x - out.points.lo.x, out.points.hi.y - out.points.lo.y);
  return out;
}

bool inside(const BBox& b, const Point& p) { return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y; }

std::vector<std::pair<Point, Point>> pairs(const Shape* s) {
  std::vector<std::pair<Point, Point>> out;
  if (s)
    for (std::size_t i = 0; i + 1 < s->points.size(); i += 2) out.push_back({s->points[i], s->points[i + 1]});
  return out;
}

TEST(SceneVoronoi, RandomPointsDrawTheDiagramTriangleWrites) {
  testing::TempDir dir("meshstep_scene_voronoi_");
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(0.0, 100.0);
  std::ostringstream node;
  node << "40 2 0 0\n";
  for (int i = 0; i < 40; ++i) node << i << ' ' << u(rng) << ' ' << u(rng) << '\n';
  const VoronoiRun r = run_voronoi(dir, dir.write("points.node", node.str()));
  const Scene& s = r.scene;
  ASSERT_FALSE(s.mesh.triangles.empty());
  ASSERT_EQ(r.files.vertices.size(), s.mesh.triangles.size());

  // Every Voronoi vertex of the files within the mesh's box is a marker, and every marker is
  // the circumcenter of a triangle of the scene's mesh (computed here: equidistant from its
  // three corners).
  const Shape* centers = s.find("voronoi_vertices");
  ASSERT_NE(centers, nullptr);
  EXPECT_EQ(centers->layer, Layer::voronoi);
  for (const Point& v : r.files.vertices) {
    if (!inside(r.points, v)) continue;
    EXPECT_TRUE(std::any_of(centers->points.begin(), centers->points.end(), [&](const Point& c) { return near(c, v, r.scale); }))
        << "the files' vertex (" << v.x << ", " << v.y << ") is not drawn";
  }
  for (const Point& c : centers->points) {
    const bool circumcenter = std::any_of(s.mesh.triangles.begin(), s.mesh.triangles.end(), [&](const auto& t) {
      const double ra = distance(c, s.mesh.points[t[0]]);
      return std::abs(distance(c, s.mesh.points[t[1]]) - ra) < 1e-9 * r.scale &&
             std::abs(distance(c, s.mesh.points[t[2]]) - ra) < 1e-9 * r.scale;
    });
    EXPECT_TRUE(circumcenter) << "marker (" << c.x << ", " << c.y << ") is no triangle's circumcenter";
  }

  // Every finite edge of the files with both ends in the mesh's box is drawn whole, and every
  // drawn edge lies on one of the files' edges (cut to the picture's box at most).
  const auto drawn = pairs(s.find("voronoi_edges"));
  std::size_t whole = 0;
  for (const auto& [a, b] : r.files.edges) {
    if (!inside(r.points, a) || !inside(r.points, b) || near(a, b, r.scale)) continue;
    ++whole;
    EXPECT_TRUE(std::any_of(drawn.begin(), drawn.end(), [&](const auto& d) {
      return (near(d.first, a, r.scale) && near(d.second, b, r.scale)) || (near(d.first, b, r.scale) && near(d.second, a, r.scale));
    })) << "edge (" << a.x << ", " << a.y << ")-(" << b.x << ", " << b.y << ") is not drawn";
  }
  EXPECT_GT(whole, 20u);
  for (const auto& [p, q] : drawn) {
    const bool on_one = std::any_of(r.files.edges.begin(), r.files.edges.end(), [&](const auto& e) {
      const auto on = [&](const Point& x) {
        const double len = distance(e.first, e.second);
        return std::abs(distance(e.first, x) + distance(x, e.second) - len) <= 1e-9 * (r.scale + len);
      };
      return on(p) && on(q);
    });
    EXPECT_TRUE(on_one) << "drawn edge (" << p.x << ", " << p.y << ")-(" << q.x << ", " << q.y << ") is on no Voronoi edge";
  }

  // Points in general position: every boundary edge is a hull edge, so every ray of the
  // files whose start is in the mesh's box is drawn, from there, in its direction, and
  // reaches beyond the mesh.
  const auto rays = pairs(s.find("voronoi_rays"));
  std::size_t rays_checked = 0;
  for (const auto& [start, direction] : r.files.rays) {
    if (!inside(r.points, start)) continue;
    ++rays_checked;
    const bool found = std::any_of(rays.begin(), rays.end(), [&](const auto& d) {
      const Point v{d.second.x - d.first.x, d.second.y - d.first.y};
      const double cross = v.x * direction.y - v.y * direction.x, dot = v.x * direction.x + v.y * direction.y;
      return near(d.first, start, r.scale) && dot > 0 &&
             std::abs(cross) <= 1e-9 * std::hypot(v.x, v.y) * std::hypot(direction.x, direction.y) &&
             !inside(r.points, d.second);
    });
    EXPECT_TRUE(found) << "the ray from (" << start.x << ", " << start.y << ") is not drawn";
  }
  EXPECT_GE(rays_checked, 3u);
  EXPECT_LE(rays.size(), r.files.rays.size());

  // The sites: the mesh's vertices, every one.
  const Shape* sites = s.find("voronoi_sites");
  ASSERT_NE(sites, nullptr);
  EXPECT_EQ(sites->points.size(), 40u);
}

// lesson.poly: a hole and a concave outline. Only its three hull edges ((0,0)-(12,0),
// (12,7)-(0,7), (0,7)-(0,0)) may send rays out, down, up and left; the hole's edges (its
// square stands on a corner: diagonal normals) and the tooth's (out to the right or
// diagonal) send none, though the files have a ray for each.
TEST(SceneVoronoi, OnlyHullEdgesSendRays) {
  testing::TempDir dir("meshstep_scene_voronoi_");
  const VoronoiRun r = run_voronoi(dir, std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly");
  const std::vector<Point> hull_normals{{0, -1}, {0, 1}, {-1, 0}};
  const auto unit = [](const Point& d) {
    const double len = std::hypot(d.x, d.y);
    return Point{d.x / len, d.y / len};
  };
  const auto is_hull_normal = [&](const Point& d) {
    const Point u = unit(d);
    return std::any_of(hull_normals.begin(), hull_normals.end(), [&](const Point& n) { return distance(u, n) < 1e-9; });
  };
  std::size_t other_rays = 0, hull_rays_inside = 0;
  for (const auto& [start, direction] : r.files.rays) {
    if (!is_hull_normal(direction)) {
      ++other_rays;
      continue;
    }
    hull_rays_inside += inside(r.points, start);
  }
  EXPECT_EQ(other_rays, 8u) << "the hole's four edges and the tooth's four";
  const auto rays = pairs(r.scene.find("voronoi_rays"));
  ASSERT_FALSE(rays.empty());
  EXPECT_GE(rays.size(), hull_rays_inside) << "every hull ray that starts in the picture";
  EXPECT_LE(rays.size(), 3u);
  for (const auto& [a, b] : rays) {
    EXPECT_TRUE(is_hull_normal({b.x - a.x, b.y - a.y})) << "a ray from (" << a.x << ", " << a.y << ") leaves no hull edge";
    EXPECT_TRUE(std::any_of(r.files.rays.begin(), r.files.rays.end(),
                            [&](const auto& f) { return near(f.first, a, r.scale); }))
        << "a ray starts at no circumcenter of the files";
  }
}

TEST(SceneVoronoi, OffUnlessAskedAndLightensTheEdgesWhenOn) {
  testing::TempDir dir("meshstep_scene_voronoi_");
  const VoronoiRun on = run_voronoi(dir, std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly");
  const replay::LogReader log(dir.file("run.mslog"));
  replay::Replay cursor(log);
  cursor.seek_event(log.event_count());
  const Scene off = build_scene(cursor, SceneOptions{});
  EXPECT_FALSE(off.visible.has(Layer::voronoi));
  for (const Shape& s : off.shapes) EXPECT_NE(s.layer, Layer::voronoi) << s.role;
  EXPECT_TRUE(on.scene.visible.has(Layer::voronoi));
  EXPECT_LT(on.scene.mesh.edge_color.a, off.mesh.edge_color.a) << "the Delaunay edges step back under the diagram";
}

}  // namespace
}  // namespace meshstep::scene
