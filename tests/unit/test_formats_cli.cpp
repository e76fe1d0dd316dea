// `-o OUT.EXT` on the commands that write a 2D mesh, GeoJSON/WKT inputs on the command
// line, and `meshstep list`'s format table.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "meshstep/io/surface_io.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_meshstep;
using testing::slurp;
using testing::TempDir;

const std::string kPlate = std::string(MESHSTEP_ASSETS) + "/examples/plate.poly";

constexpr const char* kLake = R"({"type": "Feature", "properties": {"name": "lake"},
 "geometry": {"type": "Polygon", "coordinates": [
  [[0,0],[4,0],[4,4],[0,4],[0,0]],
  [[1,1],[3,1],[3,1.5],[1.5,1.5],[1.5,2.5],[3,2.5],[3,3],[1,3],[1,1]]]}})";

TEST(FormatsCli, OutputExtensionPicksTheWriterOnEveryCommand) {
  TempDir dir;
  const std::string log = dir.file("run.mslog");
  CommandResult r = run_meshstep("refine " + kPlate + " --min-angle 25 -o " + dir.file("q.msh") + " --record " + log,
                                 dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("written to " + dir.file("q.msh")), std::string::npos) << r.out;
  EXPECT_TRUE(slurp(dir.file("q.msh")).starts_with("$MeshFormat\n4.1 0 8\n"));
  EXPECT_FALSE(fs::exists(dir.file("q.msh.node")));

  r = run_meshstep("triangulate " + kPlate + " -o " + dir.file("t.vtu"), dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(dir.file("t.vtu")).find("<UnstructuredGrid>"), std::string::npos);

  // log mesh: the run's end as an OFF file, and as Triangle's files: the same triangles.
  r = run_meshstep("log mesh " + log + " --step -1 -o " + dir.file("end.off"), dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  r = run_meshstep("log mesh " + log + " --step -1 -o " + dir.file("end"), dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const TriMesh mesh = io::read_mesh(dir.file("end"));
  const io::Surface off = io::read_surface(dir.file("end.off"));
  EXPECT_EQ(off.triangles, mesh.triangles);
  ASSERT_EQ(off.vertices.size(), mesh.points.size());
  for (std::size_t i = 0; i < off.vertices.size(); ++i) {
    EXPECT_EQ(off.vertices[i].x, mesh.points[i].x);
    EXPECT_EQ(off.vertices[i].y, mesh.points[i].y);
    EXPECT_EQ(off.vertices[i].z, 0.0);
  }

  const std::string recipe = dir.write("two.recipe", "refine --min-angle 20\nrefine --max-area 0.05\n");
  r = run_meshstep("run " + recipe + " " + kPlate + " -o " + dir.file("chain.ply"), dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(io::read_surface(dir.file("chain.ply")).triangles.empty());
}

TEST(FormatsCli, APrefixWithoutAMeshExtensionWritesTriangleFilesAsBefore) {
  TempDir dir;
  // "box.1" has an extension no writer claims: it stays a prefix.
  CommandResult r = run_meshstep("refine " + kPlate + " --min-angle 25 -o " + dir.file("box.1"), dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* ext : {".node", ".ele", ".poly"}) EXPECT_TRUE(fs::exists(dir.file(std::string("box.1") + ext)));
  EXPECT_NE(r.out.find("written to " + dir.file("box.1") + ".node, .ele, .poly"), std::string::npos) << r.out;
  // The same mesh as through the .msh writer: Triangle's files are the full record.
  r = run_meshstep("refine " + kPlate + " --min-angle 25 -o " + dir.file("box.obj"), dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(io::read_surface(dir.file("box.obj")).triangles, io::read_mesh(dir.file("box.1")).triangles);
}

TEST(FormatsCli, GeoJsonAndWktInputsAreMeshedWithTheirHoles) {
  TempDir dir;
  const std::string lake = dir.write("lake.geojson", kLake);
  CommandResult r = run_meshstep("refine " + lake + " --min-angle 28 --max-area 0.1 --stats json", dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  // Default output as for a .poly: lake.1.*
  const TriMesh mesh = io::read_mesh(dir.file("lake.1"));
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const Point &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  EXPECT_NEAR(area, 16 - 2.5, 1e-12);
  EXPECT_EQ(testing::json_field(testing::stats_line(r.out), "bounds_met"), "true");

  const std::string wkt = dir.write("lake.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1))");
  r = run_meshstep("triangulate " + wkt + " -o " + dir.file("w.msh"), dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
}

TEST(FormatsCli, MalformedPolygonFilesAreRefusedWithFileAndLine) {
  TempDir dir;
  const std::string bad = dir.write("bad.geojson", "{\"type\": \"Polygon\",\n \"coordinates\": [[[0,0],[1,0],]]}");
  CommandResult r = run_meshstep("refine " + bad + " --min-angle 20 -o " + dir.file("out.msh"), dir.path());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(bad + ":2: "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("out.msh")));
  const std::string wkt = dir.write("bad.wkt", "POLYGON ((0 0, 1 0, 1 1)\n");
  r = run_meshstep("triangulate " + wkt, dir.path());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(wkt + ":2: "), std::string::npos) << r.err;
}

TEST(FormatsCli, TriangleOnlyOptionsWithAOneFileOutputAreAUsageError) {
  TempDir dir;
  const CommandResult r = run_meshstep("triangulate " + kPlate + " -e -o " + dir.file("t.msh"), dir.path());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("-e/--edges"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("t.msh")));
}

TEST(FormatsCli, ListShowsTheFormatTable) {
  TempDir dir;
  const CommandResult r = run_meshstep("list", dir.path());
  ASSERT_EQ(r.status, 0);
  // The row of an extension: "  .msh      mesh, W: ...".
  const auto row = [&](const std::string& extension) {
    const std::size_t at = r.out.find("\n  " + extension + " ");
    return at == std::string::npos ? std::string() : r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
  };
  EXPECT_NE(row(".msh").find("mesh, W: gmsh"), std::string::npos) << r.out;
  EXPECT_NE(row(".msh").find("physical groups"), std::string::npos) << row(".msh");
  EXPECT_NE(row(".vtu").find("mesh, W: VTK"), std::string::npos) << r.out;
  EXPECT_NE(row(".geojson").find("pslg, R: GeoJSON"), std::string::npos) << r.out;
  EXPECT_NE(row(".wkt").find("pslg, R: WKT"), std::string::npos) << r.out;
  EXPECT_NE(row(".stl").find("2D mesh (-o OUT.stl): triangles at z = 0"), std::string::npos) << row(".stl");
  EXPECT_EQ(row(".poly").find("2D mesh"), std::string::npos) << row(".poly");
}

}  // namespace
}  // namespace meshstep
