// A terrain run recorded into the replay log (TerrainOptions::record): the log replays to
// the TIN the run returned, every vertex carries its sample's height, and every step says
// truthfully which triangle was worst, by how much, and which sample went in. The truths
// are measured here, independently of the algorithm's bookkeeping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/verify.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/lift.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"
#include "temp_dir.hpp"

namespace meshstep::terrain {
namespace {

using replay::EventType;

HeightGrid rolling_hills(std::size_t nx, std::size_t ny) {
  HeightGrid g;
  g.nx = nx;
  g.ny = ny;
  g.dx = 10.0;
  g.dy = 7.5;
  g.z.resize(nx * ny);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i)
      g.z[i + j * nx] = static_cast<float>(100.0 + 12.0 * std::sin(0.31 * i) * std::cos(0.23 * j) + 0.4 * i);
  return g;
}

struct Sample {
  std::size_t i, j;
};
Sample sample_at(const HeightGrid& g, const Point& p) {
  return {static_cast<std::size_t>(std::lround(p.x / g.dx)), static_cast<std::size_t>(std::lround(p.y / g.dy))};
}

// The largest vertical error of the samples in triangle abc (grid points, heights), each
// sample measured in the plane through the corners: the tests' own measure.
double worst_error_in(const HeightGrid& g, const replay::LogReader& log, const std::array<VertexId, 3>& t) {
  double x[3], y[3], z[3];
  for (int k = 0; k < 3; ++k) {
    const Sample s = sample_at(g, log.vertices()[t[k]].point);
    x[k] = static_cast<double>(s.i);
    y[k] = static_cast<double>(s.j);
    z[k] = log.vertices()[t[k]].z;
  }
  const double det = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  double worst = -1.0;
  for (auto j = static_cast<std::size_t>(std::min({y[0], y[1], y[2]})); j <= std::max({y[0], y[1], y[2]}); ++j)
    for (auto i = static_cast<std::size_t>(std::min({x[0], x[1], x[2]})); i <= std::max({x[0], x[1], x[2]}); ++i) {
      const double px = static_cast<double>(i), py = static_cast<double>(j);
      const double l1 = ((px - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (py - y[0])) / det;
      const double l2 = ((x[1] - x[0]) * (py - y[0]) - (px - x[0]) * (y[1] - y[0])) / det;
      const double l0 = 1.0 - l1 - l2;
      if (l0 < -1e-12 || l1 < -1e-12 || l2 < -1e-12) continue;
      worst = std::max(worst, std::abs(g.at(i, j) - (l0 * z[0] + l1 * z[1] + l2 * z[2])));
    }
  return worst;
}

using Corners = std::array<std::array<double, 3>, 3>;
// A triangle by its corners' positions and heights, from its smallest corner round: the
// log and the TIN number vertices differently (the TIN leaves out removed ones).
Corners canonical(Corners c) {
  while (c[0] > c[1] || c[0] > c[2]) std::rotate(c.begin(), c.begin() + 1, c.end());
  return c;
}

struct Recorded {
  Tin tin;
  TerrainReport report;
};

Recorded record(const HeightGrid& g, TerrainOptions options, const std::string& path) {
  replay::LogHeader header;
  header.algorithm = options.algorithm == TerrainAlgorithm::greedy ? "greedy" : "lepp-surface";
  header.parameters = "max_error=" + std::to_string(options.max_error) + " input_vertices=4";
  header.data_structure = options.data_structure == DataStructure::dcel ? "dcel" : "tds";
  header.insertion = "flip";
  replay::LogWriterOptions small_blocks;
  small_blocks.block_bytes = 2048;  // many blocks and keyframes: seeks cross them
  small_blocks.keyframes.min_events = 64;
  replay::LogWriter writer(path, header, small_blocks);
  options.record = &writer;
  Recorded r;
  r.tin = approximate(g, options, &r.report);
  writer.finish();
  return r;
}

// A small Lepp-surface run on g (bound 0.5), recorded into DIR/r.mslog; returns the path.
std::string record_small_run(const HeightGrid& g, const testing::TempDir& dir) {
  TerrainOptions options;
  options.max_error = 0.5;
  record(g, options, dir.file("r.mslog"));
  return dir.file("r.mslog");
}

struct Case {
  TerrainAlgorithm algorithm;
  DataStructure ds;
  bool improve, flips;
};

class TerrainRecord : public ::testing::TestWithParam<Case> {};

TEST_P(TerrainRecord, ReplaysToTheTinAndEveryStepTellsTheTruth) {
  const Case c = GetParam();
  const HeightGrid g = rolling_hills(41, 33);
  TerrainOptions options;
  options.algorithm = c.algorithm;
  options.data_structure = c.ds;
  options.max_error = 0.8;
  options.improve = c.improve;
  options.flips_3d = c.flips;
  testing::TempDir dir;
  const std::string path = dir.file("terrain.mslog");
  const Recorded run = record(g, options, path);

  const replay::LogReader log(path);
  ASSERT_TRUE(log.complete());
  ASSERT_TRUE(log.has_elevation());
  const replay::VerifyReport verified = replay::verify(log);
  EXPECT_TRUE(verified.ok) << verified.problem;

  // Every vertex stands on its sample, at the sample's height.
  std::size_t vertices = 0;
  for (const replay::VertexInfo& v : log.vertices()) {
    if (v.event == kNone) continue;
    ++vertices;
    const Sample s = sample_at(g, v.point);
    ASSERT_EQ(v.point.x, static_cast<double>(s.i) * g.dx);
    ASSERT_EQ(v.point.y, static_cast<double>(s.j) * g.dy);
    ASSERT_EQ(v.z, g.at(s.i, s.j));
  }
  EXPECT_EQ(vertices, 4 + run.report.insertions);

  // The end of the log is the TIN the run returned, triangle for triangle.
  replay::Replay cursor(log);
  cursor.seek_event(log.event_count());
  const TriMesh end = cursor.mesh();
  std::multiset<Corners> from_log, from_tin;
  std::map<std::pair<double, double>, double> z_at;
  for (const replay::VertexInfo& v : log.vertices())
    if (v.event != kNone) z_at[{v.point.x, v.point.y}] = v.z;
  for (const auto& t : end.triangles) {
    Corners k;
    for (int i = 0; i < 3; ++i) k[i] = {end.points[t[i]].x, end.points[t[i]].y, z_at.at({end.points[t[i]].x, end.points[t[i]].y})};
    from_log.insert(canonical(k));
  }
  for (const auto& t : run.tin.triangles) {
    Corners k;
    for (int i = 0; i < 3; ++i) {
      const auto p = vertex_position(g, run.tin, t[i]);
      k[i] = {p[0], p[1], p[2]};
    }
    from_tin.insert(canonical(k));
  }
  EXPECT_EQ(from_log, from_tin);

  // The steps: one refine step per insertion, one per removal, one per 3D flip.
  std::size_t refine = 0, removals = 0, flips = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    refine += log.step_kind(k) == replay::StepKind::refine;
    removals += log.step_kind(k) == replay::StepKind::remove_vertex;
    flips += log.step_kind(k) == replay::StepKind::flip_3d;
  }
  EXPECT_EQ(refine, run.report.insertions);
  EXPECT_EQ(removals, run.report.removed);
  EXPECT_EQ(flips, run.report.flips_3d);
  if (c.improve) {
    EXPECT_GT(removals, 0u);
  }
  if (c.flips) {
    EXPECT_GT(flips, 0u);
  }

  // Each refine step, at its worst-triangle test: the triangle is in the mesh, its error is
  // what the test says and misses the bound, and no triangle of the mesh is worse; the
  // sample chosen is not a vertex yet, and is the vertex the step inserts. Every fifth step
  // (the search of every triangle is slow), and the last.
  std::size_t checked = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    if (log.step_kind(k) != replay::StepKind::refine || (k % 5 != 0 && k + 1 != log.step_count())) continue;
    std::uint64_t test = 0, selected = 0, vertex = 0;
    for (std::uint64_t e = log.step_start(k); e < log.step_start(k + 1); ++e) {
      const EventType t = log.event(e).type;
      if (t == EventType::criterion_test && !test) test = e;
      if (t == EventType::point_selected) selected = e;
      if (t == EventType::vertex) vertex = e;
    }
    ASSERT_TRUE(test && selected && vertex) << "step " << k;
    const replay::Event criterion = log.event(test);
    EXPECT_EQ(criterion.code, static_cast<std::uint8_t>(replay::Criterion::vertical_error));
    const double value = criterion.value;
    const std::array<VertexId, 3> bad{criterion.ids[0], criterion.ids[1], criterion.ids[2]};
    EXPECT_GT(value, options.max_error);
    cursor.seek_event(test);
    const TriMesh now = cursor.mesh();
    double worst = 0.0;
    bool present = false;
    for (const auto& t : now.triangles) {
      std::array<VertexId, 3> ids{};
      for (int i = 0; i < 3; ++i) {
        // The mesh lists vertices by position: find their ids through the log.
        const auto it = std::find_if(log.vertices().begin(), log.vertices().end(), [&](const replay::VertexInfo& v) {
          return v.event != kNone && v.event < test && v.point == now.points[t[i]];
        });
        ids[i] = static_cast<VertexId>(it - log.vertices().begin());
      }
      worst = std::max(worst, worst_error_in(g, log, ids));
      std::array<VertexId, 3> a = ids, b = bad;
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      present = present || a == b;
    }
    EXPECT_TRUE(present) << "step " << k << ": the worst triangle is not in the mesh";
    EXPECT_NEAR(worst_error_in(g, log, bad), value, 1e-4) << "step " << k;
    EXPECT_NEAR(worst, value, 1e-4) << "step " << k << ": a triangle is worse than the one named";
    const replay::Event chosen = log.event(selected);
    EXPECT_GE(chosen.code, replay::kFirstSampleChoice);
    EXPECT_EQ(chosen.point, log.event(vertex).point);
    if (c.algorithm == TerrainAlgorithm::greedy) {
      EXPECT_EQ(chosen.code, static_cast<std::uint8_t>(replay::SampleChoice::worst_sample));
      const Sample s = sample_at(g, chosen.point);
      // Greedy's sample is the worst one: its error in the bad triangle is the test's value.
      double x[3], y[3], z[3];
      for (int i = 0; i < 3; ++i) {
        const Sample q = sample_at(g, log.vertices()[bad[i]].point);
        x[i] = static_cast<double>(q.i), y[i] = static_cast<double>(q.j), z[i] = log.vertices()[bad[i]].z;
      }
      const double det = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
      const double px = static_cast<double>(s.i), py = static_cast<double>(s.j);
      const double l1 = ((px - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (py - y[0])) / det;
      const double l2 = ((x[1] - x[0]) * (py - y[0]) - (px - x[0]) * (y[1] - y[0])) / det;
      EXPECT_NEAR(std::abs(g.at(s.i, s.j) - ((1 - l1 - l2) * z[0] + l1 * z[1] + l2 * z[2])), value, 1e-4);
    }
    ++checked;
  }
  EXPECT_GT(checked, 10u);
}

INSTANTIATE_TEST_SUITE_P(
    Runs, TerrainRecord,
    ::testing::Values(Case{TerrainAlgorithm::lepp_surface, DataStructure::tds, true, false},
                      Case{TerrainAlgorithm::lepp_surface, DataStructure::dcel, false, true},
                      Case{TerrainAlgorithm::greedy, DataStructure::tds, false, false},
                      Case{TerrainAlgorithm::greedy, DataStructure::dcel, true, true}),
    [](const auto& info) {
      const Case& c = info.param;
      return std::string(c.algorithm == TerrainAlgorithm::greedy ? "greedy" : "lepp_surface") + "_" +
             (c.ds == DataStructure::dcel ? "dcel" : "tds") + (c.improve ? "_improve" : "") + (c.flips ? "_flips" : "");
    });

TEST(TerrainRecord, RecordingDoesNotChangeTheTin) {
  const HeightGrid g = rolling_hills(30, 25);
  TerrainOptions options;
  options.max_error = 0.5;
  options.improve = true;
  const Tin plain = approximate(g, options);
  testing::TempDir dir;
  const Recorded recorded = record(g, options, dir.file("r.mslog"));
  EXPECT_EQ(plain.samples, recorded.tin.samples);
  EXPECT_EQ(plain.triangles, recorded.tin.triangles);
}

// The picture of a terrain's moment in 3D: the planar scene's overlays go onto the surface.
TEST(TerrainRecord, LiftedSceneProjectsTheStepOntoTheSurface) {
  const HeightGrid g = rolling_hills(30, 25);
  testing::TempDir dir;
  const replay::LogReader log(record_small_run(g, dir));
  replay::Replay cursor(log);
  cursor.seek_step(12);
  const scene::Scene planar = scene::build_scene(cursor, scene::SceneOptions{});
  const scene::Shape* bad = planar.find("bad_triangle");
  ASSERT_NE(bad, nullptr);
  const scene::Shape* chosen = planar.find("selected_point");
  ASSERT_NE(chosen, nullptr);

  scene::SurfaceView view;
  view.azimuth_deg = 30;
  view.elevation_deg = 40;
  view.z_scale = 3;
  const std::vector<double> heights = scene::mesh_point_heights(planar, log);
  const scene::Scene lifted = scene::lift_scene(planar, heights, view);
  EXPECT_EQ(lifted.mesh.triangles.size(), planar.mesh.triangles.size());
  EXPECT_TRUE(lifted.mesh.painter_order);
  EXPECT_EQ(lifted.highlighted.size(), planar.highlighted.size());
  EXPECT_EQ(lifted.find("circumcircle"), nullptr);
  EXPECT_NE(lifted.caption.find(planar.caption), std::string::npos);

  // Every corner of the bad triangle is a vertex: lifted to its own height and projected.
  const scene::Shape* lifted_bad = lifted.find("bad_triangle");
  ASSERT_NE(lifted_bad, nullptr);
  ASSERT_EQ(lifted_bad->points.size(), bad->points.size());
  std::map<std::pair<double, double>, double> z_at;
  for (const replay::VertexInfo& v : log.vertices())
    if (v.event != kNone) z_at[{v.point.x, v.point.y}] = v.z;
  std::multiset<std::pair<double, double>> expected, got;
  for (const Point& p : bad->points) {
    const Point q = scene::project(p, z_at.at({p.x, p.y}), view);
    expected.insert({q.x, q.y});
  }
  for (const Point& p : lifted_bad->points) got.insert({p.x, p.y});
  EXPECT_EQ(got, expected);
  // The chosen sample is a grid point: the height of its sample.
  const Point p = chosen->points.front();
  const Sample s = sample_at(g, p);
  const Point q = scene::project(p, g.at(s.i, s.j), view);
  EXPECT_NEAR(lifted.find("selected_point")->points.front().x, q.x, 1e-9);
  EXPECT_NEAR(lifted.find("selected_point")->points.front().y, q.y, 1e-9);
}

TEST(TerrainRecord, OlderFormatsCannotHoldHeights) {
  const HeightGrid g = rolling_hills(12, 10);
  TerrainOptions options;
  options.max_error = 0.5;
  testing::TempDir dir;
  replay::LogHeader header;
  header.algorithm = "lepp-surface";
  replay::LogWriterOptions v3;
  v3.format_version = 3;
  bool refused = false;
  try {
    replay::LogWriter writer(dir.file("old.mslog"), header, v3);
    options.record = &writer;
    approximate(g, options);
    writer.finish();
  } catch (const std::exception& e) {
    refused = true;
    EXPECT_NE(std::string(e.what()).find("elevation"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(refused);
  EXPECT_FALSE(std::filesystem::exists(dir.file("old.mslog")));
}

// --color-by height on a terrain's log: each triangle's value is the mean height of its
// corners, its colour viridis from the lowest corner to the highest; a planar run's log has
// no heights, and says so in its legend.
TEST(TerrainRecord, TrianglesColouredByHeightInThePlane) {
  const HeightGrid g = rolling_hills(30, 25);
  testing::TempDir dir;
  const replay::LogReader log(record_small_run(g, dir));
  replay::Replay cursor(log);
  cursor.seek_step(40);
  scene::SceneOptions by_height;
  by_height.color_by = scene::ColorBy::height;
  const scene::Scene s = scene::build_scene(cursor, by_height);
  ASSERT_TRUE(s.legend);
  EXPECT_EQ(s.legend->title, "height");
  ASSERT_EQ(s.mesh.values.size(), s.mesh.triangles.size());
  double lo = INFINITY, hi = -INFINITY;
  std::size_t lowest = 0, highest = 0;
  for (std::size_t t = 0; t < s.mesh.triangles.size(); ++t) {
    const auto& v = s.mesh.triangles[t];
    const double mean = (log.vertices()[v[0]].z + log.vertices()[v[1]].z + log.vertices()[v[2]].z) / 3.0;
    EXPECT_DOUBLE_EQ(s.mesh.values[t], mean);
    if (mean < lo) lo = mean, lowest = t;
    if (mean > hi) hi = mean, highest = t;
  }
  EXPECT_NE(s.mesh.fill[lowest], s.mesh.fill[highest]);
  // Darker at the bottom of viridis, lighter at the top.
  const auto light = [](scene::Rgba c) { return c.r + c.g + c.b; };
  EXPECT_LT(light(s.mesh.fill[lowest]), light(s.mesh.fill[highest]));

  // A run without heights: every triangle the neutral fill, the legend saying why.
  testing::TempDir other;
  {
    replay::LogHeader header;
    replay::LogWriter writer(other.file("flat.mslog"), header);
    TriangulateOptions t;
    t.record = &writer;
    Pslg square;
    square.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.3, 0.6}};
    triangulate(square, t);
    writer.finish();
  }
  const replay::LogReader flat_log(other.file("flat.mslog"));
  replay::Replay flat(flat_log);
  flat.seek_event(flat_log.event_count());
  const scene::Scene none = scene::build_scene(flat, by_height);
  ASSERT_TRUE(none.legend);
  EXPECT_EQ(none.legend->ticks.front().text, "no heights (a planar run)");
  for (const scene::Rgba& c : none.mesh.fill) EXPECT_EQ(c, none.mesh.fill.front());
}

}  // namespace
}  // namespace meshstep::terrain
