// `meshstep refine --region / --region-polygon / --region-poly`: the bounds hold where a triangle's centroid is
// in the region and not elsewhere, on a .poly and on a mesh prefix; refusals of malformed,
// empty and non-simple regions with the usual exit statuses; the region in the log.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/region.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using testing::CommandResult;

constexpr const char* kSquare =
    "# 10 x 10 square\n"
    "4 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n"
    "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
    "0\n";

// The square with a vertex at every interior point of the unit lattice: triangles of area
// 0.5, some with their centroid in any region below.
std::string lattice_square() {
  std::string points;
  int n = 4;
  for (int x = 1; x < 10; ++x)
    for (int y = 1; y < 10; ++y) points += std::to_string(++n) + " " + std::to_string(x) + " " + std::to_string(y) + "\n";
  return "# 10 x 10 square, lattice inside\n" + std::to_string(n) + " 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n" + points +
         "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n";
}

// An L of 1-wide arms, as a region: listed clockwise and out of order on purpose.
constexpr const char* kLRegion =
    "6 2 0 0\n1 1 1\n2 5 1\n3 5 2\n4 2 2\n5 2 5\n6 1 5\n"
    "6 0\n1 2 1\n2 1 6\n3 6 5\n4 5 4\n5 4 3\n6 3 2\n"
    "0\n";

constexpr const char* kBowtie =
    "4 2 0 0\n1 0 0\n2 2 2\n3 2 0\n4 0 2\n"
    "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
    "0\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Outcome {
  std::size_t inside = 0, bad_inside = 0, bad_outside = 0;
};

// Triangles missing 25 degrees or an area of 0.02, with their centroids in or out of the
// region (this file's own measures).
Outcome outcome(const TriMesh& m, const RefineRegion& region) {
  Outcome o;
  for (const auto& t : m.triangles) {
    const Point &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    double smallest = 180.0;
    for (int i = 0; i < 3; ++i) {
      const Point &p = m.points[t[i]], &q = m.points[t[(i + 1) % 3]], &r = m.points[t[(i + 2) % 3]];
      const double ux = q.x - p.x, uy = q.y - p.y, vx = r.x - p.x, vy = r.y - p.y;
      smallest = std::min(smallest, std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / std::numbers::pi);
    }
    const double area = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    const bool bad = area > 0.02 * (1 + 1e-12) || smallest < 25 - 1e-9;
    if (region.contains({(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0})) {
      ++o.inside;
      o.bad_inside += bad;
    } else {
      o.bad_outside += bad;
    }
  }
  return o;
}

class RefineRegionCli : public testing::CliTest {
 protected:
  RefineRegionCli() : CliTest("meshstep_refine_region_cli_") {}

  // Refines `input` with `options` into `prefix` and checks the outcome in `region`.
  void expect_refined_in(const std::string& input, const std::string& options, const std::string& prefix,
                         const RefineRegion& region) {
    const CommandResult r = meshstep("refine " + input + " --min-angle 25 --max-area 0.02 -q " + options + " -o " + prefix);
    ASSERT_EQ(r.status, 0) << r.err;
    const Outcome o = outcome(io::read_mesh(prefix), region);
    EXPECT_GT(o.inside, 50u);
    EXPECT_EQ(o.bad_inside, 0u);
    EXPECT_GT(o.bad_outside, 5u);
  }
};

TEST_F(RefineRegionCli, ABoxOrAPolygonOnEveryStructure) {
  const std::string input = write("square.poly", lattice_square());
  const std::string l_poly = write("l.poly", kLRegion);
  const RefineRegion box = RefineRegion::box({1, 1}, {3, 3});
  const RefineRegion l = RefineRegion::polygon({{1, 1}, {5, 1}, {5, 2}, {2, 2}, {2, 5}, {1, 5}});
  for (const char* structure : {"--ds tds --insertion flip", "--ds dcel --insertion cavity"}) {
    SCOPED_TRACE(structure);
    const std::string boxed = dir_.file("boxed"), ell = dir_.file("ell");
    expect_refined_in(input, std::string(structure) + " --region 1,1,3,3", boxed, box);
    expect_refined_in(input, std::string(structure) + " --region-poly " + l_poly, ell, l);
    // The same L written out on the command line (--region-polygon), clockwise as the file's.
    const std::string inline_ell = dir_.file("inline_ell");
    expect_refined_in(input, std::string(structure) + " --region-polygon 1,1,1,5,2,5,2,2,5,2,5,1", inline_ell, l);
    EXPECT_EQ(io::read_mesh(inline_ell).triangles.size(), io::read_mesh(ell).triangles.size());
    for (const std::string& out : {boxed, ell, inline_ell}) {
      const CommandResult check = meshstep("check " + out + " --poly " + input + " -q");
      EXPECT_EQ(check.status, 0) << check.out << check.err;
    }
  }
}

// A mesh written earlier, refined in part: PREFIX in, PREFIX's next number out.
TEST_F(RefineRegionCli, PartOfAMeshPrefix) {
  const std::string input = write("square.poly", kSquare);
  const std::string prefix = dir_.file("square.1");
  ASSERT_EQ(meshstep("refine " + input + " --min-angle 20 --max-area 2 -q -o " + prefix).status, 0);
  const CommandResult r = meshstep("refine " + prefix + " --min-angle 25 --max-area 0.02 --region 1,1,3,3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "re-refinement")) << r.err;
  EXPECT_TRUE(contains(r.err, "only in the box 1,1,3,3")) << r.err;
  const Outcome o = outcome(io::read_mesh(dir_.file("square.2")), RefineRegion::box({1, 1}, {3, 3}));
  EXPECT_GT(o.inside, 50u);
  EXPECT_EQ(o.bad_inside, 0u);
  EXPECT_GT(o.bad_outside, 5u);
  EXPECT_EQ(meshstep("check " + dir_.file("square.2") + " --poly " + input + " -q").status, 0);
}

TEST_F(RefineRegionCli, RefusesMalformedEmptyAndNonSimpleRegions) {
  const std::string input = write("square.poly", kSquare);
  const auto refused = [&](const std::string& options, int status, const std::string& message) {
    SCOPED_TRACE(options);
    const CommandResult r = meshstep("refine " + input + " --min-angle 25 " + options + " -o " + dir_.file("out"));
    EXPECT_EQ(r.status, status) << r.err;
    EXPECT_TRUE(contains(r.err, message)) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir_.file("out.node")));
  };
  refused("--region 1,2,3", 2, "--region: a region box is X0,Y0,X1,Y1 (four numbers separated by commas), not '1,2,3'");
  refused("--region 1,a,3,4", 2, "not '1,a,3,4'");
  refused("--region 3,1,1,3", 2, "--region: the region box 3,1,1,3 is empty: X0 must be below X1 and Y0 below Y1");
  refused("--region 0,0,inf,1", 2, "--region: a region box's coordinates must be finite numbers");
  refused("--region 1,1,3,3 --region-poly " + write("l.poly", kLRegion), 2, "give one");
  const std::string bow = write("bow.poly", kBowtie);
  refused("--region-poly " + bow, 1, bow + ": a region polygon's segment 1 and segment 3 touch or cross");
  refused("--region-poly " + dir_.file("absent.poly"), 1, "absent.poly");
  const std::string broken = write("broken.poly", "4 2 0 0\n1 0 0\n2 1 0\n3 x 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n");
  refused("--region-poly " + broken, 1, broken + ":4:");
  refused("--region-poly " + input + " --region 1,1,3,3", 2, "give one");
  refused("--region-polygon 0,0,2,2,2,0,0,2", 2,
          "--region-polygon: a region polygon's edge 1 (0,0 to 2,2) and edge 3 (2,0 to 0,2) touch or cross");
  refused("--region-polygon 1,1,3,3", 2, "--region-polygon: a region polygon is X0,Y0,X1,Y1,X2,Y2,... (at least 3");
  refused("--region-polygon 1,1,3,1,3,3 --region 1,1,3,3", 2, "give one");
}

// The plain square triangulates into two triangles whose centroids, (6.7, 3.3) and
// (3.3, 6.7), lie outside the box: nothing is tested, nothing refined, and the run says so.
TEST_F(RefineRegionCli, ARegionWithNoCentroidInItIsNamed) {
  const std::string input = write("square.poly", kSquare);
  const CommandResult r = meshstep("refine " + input + " --max-area 0.02 --region 1,1,3,3 --stats json -o " +
                                   dir_.file("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "no triangle has its centroid in the region")) << r.err;
  EXPECT_TRUE(contains(r.out, "\"steiner\":0")) << r.out;
  const CommandResult lattice = meshstep("refine " + write("lattice.poly", lattice_square()) +
                                         " --max-area 0.02 --region 1,1,3,3 -o " + dir_.file("out"));
  ASSERT_EQ(lattice.status, 0) << lattice.err;
  EXPECT_FALSE(contains(lattice.err, "no triangle has its centroid")) << lattice.err;
}

TEST_F(RefineRegionCli, TheLogRecordsTheRegion) {
  const std::string input = write("square.poly", lattice_square());
  const std::string log = dir_.file("run.mslog");
  const CommandResult r = meshstep("refine " + input + " --max-area 0.05 --region 1,1,3,3 -q --record " + log +
                                   " -o " + dir_.file("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  const CommandResult info = meshstep("log info " + log);
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_TRUE(contains(info.out, "region=box:1,1,3,3")) << info.out;
  const CommandResult verify = meshstep("log verify " + log);
  EXPECT_EQ(verify.status, 0) << verify.out << verify.err;
}

}  // namespace
}  // namespace meshstep
