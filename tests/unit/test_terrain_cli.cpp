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

// Issue 31, fault 1: ncols x nrows wrapped 64 bits (2^32 x 2^32 = 0, (2^62 + 1) x 4 = 4),
// so the file's few values "filled" the grid: `refine --size` then read past them (a
// segfault), and `terrain` said every value was NODATA. Every reader of the header now
// refuses it at the later count's line: the size grid, the terrain, its tiles.
TEST(TerrainCli, GridCountsWhoseProductWrapsAreRefusedAtTheirLineByEveryReader) {
  TempDir dir;
  const auto square = dir.path() / "square.poly";
  std::ofstream(square) << "4 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n";
  const auto tail = "xllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value 0\n";
  const std::string headers[] = {std::string("ncols 4294967296\nnrows 4294967296\n") + tail,
                                 std::string("ncols 4611686018427387905\nnrows 4\n") + tail + "1 2 3 4\n"};
  for (const std::string& text : headers) {
    const auto grid = dir.path() / "wraps.asc";
    std::ofstream(grid) << text;
    for (const std::string& command : {"terrain " + grid.string() + " --max-error 1",
                                      "terrain " + grid.string() + " --max-error 1 --tile 4",
                                      "refine " + square.string() + " --size " + grid.string()}) {
      const auto r = run_meshstep(command, dir.path());
      EXPECT_EQ(r.status, 1) << command << "\n" << r.err;
      EXPECT_NE(r.err.find(grid.string() + ":2: "), std::string::npos) << command << "\n" << r.err;
      EXPECT_NE(r.err.find("too large a grid"), std::string::npos) << command << "\n" << r.err;
    }
  }
}

// Issue 31, fault 3: the height range was taken in float, and -3e38 .. 3e38 spans 6e38:
// an infinite range, an infinite bound (JSON null), two triangles and an error of 6e38
// passed as within it. Now the range is a double, in the whole-grid run and the tiles'.
TEST(TerrainCli, APercentBoundOverHeightsSpanningMoreThanAFloatIsMet) {
  TempDir dir;
  const auto grid = dir.path() / "extreme.asc";
  std::ofstream(grid) << "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
                         "-3e38 0 3e38\n3e38 -3e38 0\n0 3e38 -3e38\n";
  for (const std::string tiles : {"", " --tile 2"}) {
    const auto r = run_meshstep("terrain " + grid.string() + " --max-error 50% --stats json -q" + tiles, dir.path());
    ASSERT_EQ(r.status, 0) << tiles << "\n" << r.err;
    const std::string json = stats_line(r.out);
    ASSERT_NE(field(json, "bound"), "null") << json;
    const double bound = std::stod(field(json, "bound"));
    EXPECT_NEAR(bound, 3e38, 1e32) << json;  // half of 6e38
    EXPECT_LE(std::stod(field(json, "max_error")), bound) << json;
  }
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
