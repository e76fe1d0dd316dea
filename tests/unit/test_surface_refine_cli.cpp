// meshstep refine on a 3D surface: longest-edge bisection with edges measured in 3D.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "meshstep/io/surface_io.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using testing::run_meshstep;
using testing::TempDir;

// A unit cube, 12 triangles facing out.
std::filesystem::path write_cube(const std::filesystem::path& dir) {
  const auto path = dir / "cube.off";
  std::ofstream(path) << "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                         "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
                         "3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";
  return path;
}

double area(const io::Surface& s) {
  double sum = 0.0;
  for (const auto& t : s.triangles) {
    const auto &a = s.vertices[t[0]], &b = s.vertices[t[1]], &c = s.vertices[t[2]];
    const double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
    sum += 0.5 * std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
  }
  return sum;
}

TEST(SurfaceRefineCli, BisectsACubeKeepingItClosedAndItsArea) {
  TempDir dir;
  const auto cube = write_cube(dir.path());
  const auto out = dir.path() / "fine.ply";
  const auto r = run_meshstep("refine " + cube.string() + " --algorithm lepp-bisection --size 0.2 -o " + out.string(),
                              dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const io::Surface s = io::read_surface(out.string());
  EXPECT_GT(s.triangles.size(), 12u * 16);
  const io::SurfaceReport report = io::report_surface(s);
  EXPECT_TRUE(report.clean()) << io::describe(report);
  EXPECT_EQ(report.boundary_edges, 0u);
  EXPECT_NEAR(area(s), 6.0, 1e-12);
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto &p = s.vertices[t[k]], &q = s.vertices[t[(k + 1) % 3]];
      EXPECT_LE(std::hypot(p.x - q.x, p.y - q.y, p.z - q.z), 0.2);
    }
}

// --flip-dihedral: alone, or after the bisection; a coplanar thin pair takes its other
// diagonal. Bad bounds and planar inputs are refused.
TEST(SurfaceRefineCli, FlipsEdgesWithinADihedralBound) {
  TempDir dir;
  const auto rhombus = dir.path() / "rhombus.off";
  std::ofstream(rhombus) << "OFF\n4 2 0\n-2 0 0\n2 0 0\n0 0.5 0\n0 -0.5 0\n3 0 1 2\n3 1 0 3\n";
  const auto out = dir.path() / "flipped.off";
  const auto r = run_meshstep("refine " + rhombus.string() + " --algorithm lepp-bisection --flip-dihedral 0 -o " +
                                  out.string() + " --stats json -q",
                              dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"flips\":1"), std::string::npos) << r.out;
  const io::Surface s = io::read_surface(out.string());
  ASSERT_EQ(s.triangles.size(), 2u);
  for (const auto& t : s.triangles) EXPECT_TRUE(std::count(t.begin(), t.end(), 2u) && std::count(t.begin(), t.end(), 3u));
  EXPECT_NEAR(area(s), 2.0, 1e-12);
  const auto both = run_meshstep("refine " + rhombus.string() + " --algorithm lepp-bisection --size 1 --flip-dihedral 1 "
                                 "--no-output --stats json -q", dir.path());
  EXPECT_EQ(both.status, 0) << both.err;
  EXPECT_NE(both.out.find("\"bisections\":"), std::string::npos) << both.out;
  for (const char* bad : {"-1", "200", "x"}) {
    const auto refused = run_meshstep("refine " + rhombus.string() + " --algorithm lepp-bisection --flip-dihedral " + bad +
                                      " --no-output", dir.path());
    EXPECT_EQ(refused.status, 2) << bad << ": " << refused.err;
  }
  const auto planar = dir.path() / "tri.node";
  std::ofstream(planar) << "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n";
  const auto refused = run_meshstep("refine " + planar.string() + " --flip-dihedral 1 --no-output", dir.path());
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_NE(refused.err.find("3D surface"), std::string::npos) << refused.err;
}

// --record: the loading, every bisection and every flip go into a replay log with heights,
// which `log verify` replays and `render --orbit` draws in 3D (SVG: no OpenGL needed). A
// failed run leaves no log.
TEST(SurfaceRefineCli, RecordsBisectionAndFlipsForReplayIn3D) {
  TempDir dir;
  const auto cube = write_cube(dir.path());
  const std::string log = (dir.path() / "cube.mslog").string();
  auto r = run_meshstep("refine " + cube.string() + " --algorithm lepp-bisection --size 0.4 --flip-dihedral 0 --ds dcel "
                        "--no-output -q --record " + log, dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  r = run_meshstep("log verify -q " + log, dir.path());
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  r = run_meshstep("log dump " + log, dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("step_begin bisect"), std::string::npos);
  EXPECT_NE(r.out.find("criterion_test size failed"), std::string::npos);
  EXPECT_NE(r.out.find("split_edge bisection"), std::string::npos);
  EXPECT_NE(r.out.find("elevation vertex=7"), std::string::npos);  // the cube's last corner
  const std::string svg = (dir.path() / "cube.svg").string();
  r = run_meshstep("render " + log + " --step 20 --orbit 30,30 -q -o " + svg, dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string picture = testing::slurp(svg);
  EXPECT_NE(picture.find("bisected (Lepp of"), std::string::npos);
  EXPECT_NE(picture.find("3D 30\u00B0, 30\u00B0"), std::string::npos);

  const std::string failed = (dir.path() / "failed.mslog").string();
  r = run_meshstep("refine " + (dir.path() / "missing.off").string() + " --algorithm lepp-bisection --size 1 --record " +
                       failed, dir.path());
  EXPECT_EQ(r.status, 1);
  EXPECT_FALSE(std::filesystem::exists(failed));
  EXPECT_FALSE(std::filesystem::exists(failed + ".partial"));
}

// Issue 31: bisected to --max-area, then flipped, every triangle stays within the bound
// (the flips that would break it are not taken), and the summary says the bounds were met.
// Stopped by --max-triangles, the summary counts the triangles over the bounds instead, in
// words and in --stats json.
TEST(SurfaceRefineCli, FlipsKeepTheBoundsAndTheSummaryCountsTheTrianglesOverThem) {
  TempDir dir;
  const auto quad = dir.path() / "quad.off";
  std::ofstream(quad) << "OFF\n4 2 0\n0.18 0.19 0\n0.99 -0.14 0\n-0.3 1.1 0\n0.98 1.16 0\n3 0 1 3\n3 0 3 2\n";
  const auto out = dir.path() / "fine.off";
  for (const char* ds : {"tds", "dcel"}) {
    const auto r = run_meshstep("refine " + quad.string() + " -a lepp-bisection --max-area 0.3 --flip-dihedral 0 --ds " +
                                    ds + " --stats json -o " + out.string(),
                                dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("; bounds met"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"bounds_met\":true,\"over_bounds\":0"), std::string::npos) << r.out;
    const io::Surface s = io::read_surface(out.string());
    ASSERT_EQ(s.triangles.size(), 4u);
    for (const auto& t : s.triangles) {
      io::Surface one{s.vertices, {t}};
      EXPECT_LE(area(one), 0.3);
    }
  }
  const auto capped = run_meshstep("refine " + quad.string() + " -a lepp-bisection --max-area 0.05 --size 0.3 "
                                   "--max-triangles 10 --flip-dihedral 0 --stats json --no-output",
                                   dir.path());
  ASSERT_EQ(capped.status, 0) << capped.err;
  EXPECT_NE(capped.err.find("stopped at --max-triangles 10: bounds missed by 10 of 10 triangles (10 over --size, "),
            std::string::npos)
      << capped.err;
  EXPECT_NE(capped.out.find("; bounds missed by 10 of 10 triangles"), std::string::npos) << capped.out;
  EXPECT_NE(capped.out.find("\"bounds_met\":false,\"over_bounds\":10,\"over_size\":10,\"over_max_area\":"),
            std::string::npos)
      << capped.out;
}

TEST(SurfaceRefineCli, TheDefaultOutputIsNumberedLikeTriangles) {
  TempDir dir;
  const auto cube = write_cube(dir.path());
  const auto r = run_meshstep("refine " + cube.string() + " --algorithm lepp-bisection --max-area 0.1 -q", dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "cube.1.off"));
}

TEST(SurfaceRefineCli, RefusesWhatDoesNotApplyAndBadFiles) {
  TempDir dir;
  const auto cube = write_cube(dir.path());
  EXPECT_EQ(run_meshstep("refine " + cube.string() + " --size 0.2", dir.path()).status, 2);  // offcenter
  EXPECT_EQ(run_meshstep("refine " + cube.string() + " --algorithm lepp-bisection --min-angle 20", dir.path()).status, 2);
  EXPECT_EQ(run_meshstep("refine " + cube.string() + " --algorithm lepp-bisection", dir.path()).status, 2);
  const auto bad = dir.path() / "bad.off";
  std::ofstream(bad) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 x\n3 0 1 2\n";
  const auto r = run_meshstep("refine " + bad.string() + " --algorithm lepp-bisection --size 1", dir.path());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(bad.string() + ":5:"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace meshstep
