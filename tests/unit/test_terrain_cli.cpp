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
