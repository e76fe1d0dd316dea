// meshstep terrain, as a user runs it: outputs in every format, the statistics, and a clear
// refusal of every bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "meshstep/io/surface_io.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using testing::run_meshstep;
using testing::TempDir;
using testing::stats_line;
const auto& field = testing::json_field;

// A 30 x 20 grid of smooth hills, with one NODATA cell.
std::filesystem::path write_hills(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / "hills.asc";
  std::ofstream out(path);
  out << "ncols 30\nnrows 20\nxllcorner 0\nyllcorner 0\ncellsize 5\nNODATA_value -9999\n";
  for (int j = 0; j < 20; ++j) {
    for (int i = 0; i < 30; ++i)
      out << (i == 7 && j == 5 ? -9999.0 : 50 + 10 * std::sin(i * 0.3) * std::cos(j * 0.25)) << ' ';
    out << '\n';
  }
  return path;
}

TEST(TerrainCli, WritesEverySurfaceFormatAndMeasuresEverySample) {
  TempDir dir;
  const auto grid = write_hills(dir.path());
  for (const std::string out : {"t.obj", "t.off", "t.ply", "t.stl"}) {
    const auto r = run_meshstep("terrain " + grid.string() + " --max-error 0.5 -o " + (dir.path() / out).string() +
                                    " --stats json",
                                dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string json = stats_line(r.out);
    EXPECT_LE(std::stod(field(json, "max_error")), 0.5) << json;
    EXPECT_EQ(field(json, "samples"), "599");  // 600 less the NODATA cell
    const io::Surface s = io::read_surface((dir.path() / out).string());
    EXPECT_EQ(std::to_string(s.triangles.size()), field(json, "triangles")) << out;
    EXPECT_EQ(std::to_string(s.vertices.size()), field(json, "vertices")) << out;
    const io::SurfaceReport report = io::report_surface(s);
    EXPECT_TRUE(report.clean()) << io::describe(report);
    EXPECT_EQ(report.boundary_loops, 1u);
  }
}

TEST(TerrainCli, APercentBoundIsAShareOfTheHeightRange) {
  TempDir dir;
  const auto grid = write_hills(dir.path());
  const auto r = run_meshstep("terrain " + grid.string() + " --max-error 1% --stats json -q", dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const double bound = std::stod(field(r.out, "bound"));
  EXPECT_GT(bound, 0.15);  // 1% of about 20
  EXPECT_LT(bound, 0.21);
}

TEST(TerrainCli, ASolidBaseClosesTheStl) {
  TempDir dir;
  const auto grid = write_hills(dir.path());
  const auto stl = dir.path() / "solid.stl";
  const auto r = run_meshstep("terrain " + grid.string() + " --max-error 1 --base 10 -o " + stl.string(), dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const io::SurfaceReport report = io::report_surface(io::read_surface(stl.string()));
  EXPECT_TRUE(report.clean()) << io::describe(report);
  EXPECT_EQ(report.boundary_edges, 0u);
}

TEST(TerrainCli, TriangleFilesCarryTheHeightAsAnAttribute) {
  TempDir dir;
  const auto grid = write_hills(dir.path());
  const auto r = run_meshstep("terrain " + grid.string() + " --max-error 1 -o " + (dir.path() / "tin.node").string(),
                              dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const TriMesh mesh = io::read_mesh((dir.path() / "tin").string());
  EXPECT_EQ(mesh.attributes_per_vertex, 1u);
  EXPECT_GT(mesh.triangles.size(), 2u);
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    EXPECT_GE(mesh.vertex_attributes[v], 39.0);
    EXPECT_LE(mesh.vertex_attributes[v], 61.0);
  }
}

TEST(TerrainCli, BadInputIsRefusedWithWhereAndWhy) {
  TempDir dir;
  const auto grid = write_hills(dir.path());
  const auto bad = dir.path() / "bad.asc";
  std::ofstream(bad) << "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n4 x 6\n";
  const auto r1 = run_meshstep("terrain " + bad.string() + " --max-error 1", dir.path());
  EXPECT_EQ(r1.status, 1);
  EXPECT_NE(r1.err.find(bad.string() + ":7:"), std::string::npos) << r1.err;

  const auto r2 = run_meshstep("terrain " + grid.string() + " --max-error -3", dir.path());
  EXPECT_EQ(r2.status, 2);
  const auto r3 = run_meshstep("terrain " + grid.string() + " --max-error 1 -a nope", dir.path());
  EXPECT_EQ(r3.status, 2);
  EXPECT_NE(r3.err.find("unknown terrain algorithm"), std::string::npos);
  const auto r4 = run_meshstep("terrain " + grid.string(), dir.path());
  EXPECT_EQ(r4.status, 2);
  EXPECT_NE(r4.err.find("--max-error"), std::string::npos);
  const auto r5 = run_meshstep("terrain " + grid.string() + " --max-error 1 -o " + (dir.path() / "x.dxf").string(),
                               dir.path());
  EXPECT_EQ(r5.status, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.dxf"));
}

TEST(TerrainCli, TheTriangleCapWarnsAndStops) {
  TempDir dir;
  const auto grid = write_hills(dir.path());
  const auto r = run_meshstep("terrain " + grid.string() + " --max-error 0 --max-triangles 50 --stats json", dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("stopped at --max-triangles 50"), std::string::npos) << r.err;
  EXPECT_EQ(field(stats_line(r.out), "capped"), "true");
}

}  // namespace
}  // namespace meshstep

namespace meshstep {
namespace {

// --record: the run goes into a replay log with heights; `log verify` replays it, and a
// moment of it draws in 3D as SVG (no OpenGL needed). A planar run's log has no heights:
// --orbit refuses it. --record does not go with --tile.
TEST(TerrainCli, RecordsARunThatReplaysAndDrawsIn3D) {
  TempDir dir;
  const auto grid = write_hills(dir.path());
  const std::string log = (dir.path() / "t.mslog").string();
  auto r = run_meshstep("terrain " + grid.string() + " --max-error 0.5 -q --record " + log, dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  r = run_meshstep("log verify -q " + log, dir.path());
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  r = run_meshstep("log dump " + log, dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("criterion_test vertical_error failed"), std::string::npos);
  EXPECT_NE(r.out.find("point_selected terminal_"), std::string::npos);
  EXPECT_NE(r.out.find("elevation vertex="), std::string::npos);

  const std::string svg = (dir.path() / "s.svg").string();
  r = run_meshstep("render " + log + " --step 10 --orbit 30,40 --z-scale 2 -q -o " + svg, dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = testing::slurp(svg);
  EXPECT_NE(text.find("3D 30\u00B0, 40\u00B0, heights \u00D72"), std::string::npos);
  EXPECT_NE(text.find("vertical error"), std::string::npos);

  const std::string poly = (dir.path() / "square.poly").string();
  std::ofstream(poly) << "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n0 0\n0\n";
  const std::string planar = (dir.path() / "p.mslog").string();
  ASSERT_EQ(run_meshstep("triangulate " + poly + " -q --no-output --record " + planar, dir.path()).status, 0);
  r = run_meshstep("render " + planar + " --orbit 30,40 -o " + (dir.path() / "p.svg").string(), dir.path());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("terrain's replay log"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "p.svg"));

  r = run_meshstep("terrain " + grid.string() + " --max-error 0.5 --tile 10 --record " + log + ".tiles", dir.path());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--record"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(log + ".tiles"));
}

}  // namespace
}  // namespace meshstep
