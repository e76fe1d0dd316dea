// `meshstep refine` and `meshstep list`: the refinement command line's contract (outputs,
// --stats json, exit statuses, error messages, recording), run through the real binary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "meshstep/check/quality.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/registry.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;

using testing::CommandResult;

constexpr const char* kSquareWithHole =
    "# 4 x 4 square with a 2 x 2 square hole\n"
    "8 2 0 1\n"
    "1 0 0 1\n2 4 0 1\n3 4 4 1\n4 0 4 1\n5 1 1 2\n6 3 1 2\n7 3 3 2\n8 1 3 2\n"
    "8 1\n"
    "1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n"
    "1\n1 2 2\n";

constexpr const char* kLShape =
    "# an L: 3 x 3 with the 2 x 2 top-right corner cut away\n"
    "6 2 0 0\n"
    "1 0 0\n2 3 0\n3 3 1\n4 1 1\n5 1 3\n6 0 3\n"
    "6 0\n"
    "1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n"
    "0\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The last line of standard output, which --stats json makes one JSON object.
std::string last_line(const std::string& out) {
  std::string s = out;
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s.substr(s.find_last_of('\n') == std::string::npos ? 0 : s.find_last_of('\n') + 1);
}

// The raw value of "key" in a one-line JSON object (the first occurrence), or "" if absent.
std::string json_value(const std::string& json, const std::string& key) {
  const std::string tag = "\"" + key + "\":";
  const std::size_t at = json.find(tag);
  if (at == std::string::npos) return "";
  std::size_t end = at + tag.size();
  if (end < json.size() && json[end] == '"') {
    const std::size_t close = json.find('"', end + 1);
    return json.substr(end + 1, close - end - 1);
  }
  const std::size_t stop = json.find_first_of(",}", end);
  return json.substr(end, stop - end);
}

double json_number(const std::string& json, const std::string& key) {
  const std::string v = json_value(json, key);
  EXPECT_FALSE(v.empty()) << key << " missing in " << json;
  return v.empty() ? NAN : std::strtod(v.c_str(), nullptr);
}

class RefineCli : public testing::CliTest {
 protected:
  RefineCli() : CliTest("meshstep_refine_cli_") {}
};

// Both inputs, with both algorithms and both data structures and insertions: 30 degrees is
// met, the files are written and read back, and the mesh passes `meshstep check`.
TEST_F(RefineCli, MeetsThirtyDegreesAndWritesAValidMesh) {
  const std::string inputs[] = {write("hole.poly", kSquareWithHole), write("ell.poly", kLShape)};
  const char* configs[] = {"--algorithm circumcenter", "--algorithm offcenter --ds dcel --insertion cavity"};
  int run = 0;
  for (const std::string& input : inputs) {
    for (const char* config : configs) {
      SCOPED_TRACE(input + " " + config);
      const std::string prefix = dir_.file("out" + std::to_string(run++));
      const CommandResult r = meshstep("refine " + input + " " + config + " --min-angle 30 -o " + prefix +
                                       " --stats json");
      ASSERT_EQ(r.status, 0) << r.err;
      for (const char* ext : {".node", ".ele", ".poly"}) EXPECT_TRUE(fs::exists(prefix + ext)) << ext;
      const std::string json = last_line(r.out);
      ASSERT_EQ(json.front(), '{') << r.out;
      ASSERT_EQ(json.back(), '}') << r.out;
      EXPECT_EQ(json_value(json, "bounds_met"), "true") << json;
      EXPECT_EQ(json_value(json, "stopped_by_cap"), "false") << json;
      EXPECT_EQ(json_value(json, "bad_triangles"), "0") << json;
      EXPECT_GE(json_number(json, "min_angle"), 30.0) << json;
      EXPECT_GT(json_number(json, "steiner"), 0.0) << json;  // 30 degrees needs new vertices here
      for (const char* key : {"input", "algorithm", "selection", "vertices", "triangles", "segment_splits",
                              "rejected_points", "skipped_small_angle", "unsplittable_segments",
                              "below_min_angle", "bad_near_small_input_angle", "max_angle", "ds", "insertion",
                              "ms", "read", "triangulate", "refine", "write"})
        EXPECT_TRUE(contains(json, std::string("\"").append(key).append("\":"))) << key << " in " << json;
      EXPECT_EQ(json_value(json, "algorithm"), contains(config, "offcenter") ? "offcenter" : "circumcenter");
      EXPECT_EQ(json_value(json, "ds"), contains(config, "dcel") ? "dcel" : "tds");

      // The summary line says so too.
      EXPECT_TRUE(contains(r.out, input + ": ")) << r.out;
      EXPECT_TRUE(contains(r.out, "bounds met")) << r.out;

      // The written mesh is what the statistics describe, and it is a valid mesh of the input.
      const TriMesh mesh = io::read_mesh(prefix);
      EXPECT_EQ(std::to_string(mesh.triangles.size()), json_value(json, "triangles"));
      EXPECT_EQ(std::to_string(mesh.points.size()), json_value(json, "vertices"));
      EXPECT_GE(angle_stats(mesh).min_angle_deg, 30.0 - 1e-9);
      const CommandResult c = meshstep("check " + prefix + " --poly " + input + " -q");
      EXPECT_EQ(c.status, 0) << c.err;
    }
  }
}

// lepp-bisection: driven by an area bound, not Delaunay but conforming (`check --no-delaunay`
// accepts it); without a size bound, or with an angle bound, a clear error.
TEST_F(RefineCli, LeppBisectionToAnAreaBound) {
  const std::string input = write("hole.poly", kSquareWithHole);
  const std::string prefix = dir_.file("bisected");
  const CommandResult r =
      meshstep("refine " + input + " --algorithm lepp-bisection --max-area 0.01 -o " + prefix + " --stats json");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = last_line(r.out);
  EXPECT_EQ(json_value(json, "bounds_met"), "true") << json;
  EXPECT_EQ(json_value(json, "insertion"), "bisection") << json;
  EXPECT_GE(json_number(json, "triangles"), 1200.0) << "12 square units at 0.01 each";
  EXPECT_EQ(meshstep("check " + prefix + " --poly " + input + " --no-delaunay -q").status, 0);

  const CommandResult none = meshstep("refine " + input + " --algorithm lepp-bisection -o " + prefix);
  EXPECT_EQ(none.status, 2) << none.err;
  EXPECT_TRUE(contains(none.err, "lepp-bisection needs a bound: --max-area or --size")) << none.err;
  const CommandResult angle = meshstep("refine " + input + " --algorithm lepp-bisection --min-angle 25 -o " + prefix);
  EXPECT_EQ(angle.status, 1) << angle.err;
  EXPECT_TRUE(contains(angle.err, "cannot improve angles")) << angle.err;
  // --insertion bisection composes with any selection-free run the same way.
  const CommandResult composed =
      meshstep("refine " + input + " --algorithm circumcenter --insertion bisection --max-area 0.01 -o " + prefix +
               " --stats json");
  ASSERT_EQ(composed.status, 0) << composed.err;
  EXPECT_EQ(json_value(last_line(composed.out), "triangles"), json_value(json, "triangles"));
}

// improve: the plain run's Steiner vertices minus the removed ones, a valid mesh that still
// meets the bound; --improve composes it with another selection; not with bisection.
// A .poly whose regions carry maximum areas gives the area-only algorithms their bound; a
// .poly without them is refused before any work, with the ways to give one.
TEST_F(RefineCli, RegionalAreasAreABoundOfTheirOwn) {
  const std::string regions = write("regions.poly",
                                    "# 4 x 4 square cut in two; left half area 0.01, right half 0.1\n"
                                    "6 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 2 0\n6 2 4\n"
                                    "7 0\n1 1 5\n2 5 2\n3 2 3\n4 3 6\n5 6 4\n6 4 1\n7 5 6\n0\n"
                                    "2\n1 1 2 1 0.01\n2 3 2 2 0.1\n");
  for (const char* algorithm : {"lepp-bisection", "midpoint-area"}) {
    SCOPED_TRACE(algorithm);
    const CommandResult r = meshstep("refine " + regions + " --algorithm " + algorithm + " --no-output --stats json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(json_value(last_line(r.out), "bounds_met"), "true") << r.out;
    EXPECT_GT(json_number(last_line(r.out), "triangles"), 800.0) << r.out;  // 8 square units at 0.01
  }
  const CommandResult plain = meshstep("refine " + write("ell.poly", kLShape) + " --algorithm lepp-bisection");
  EXPECT_EQ(plain.status, 2) << plain.err;
  EXPECT_TRUE(contains(plain.err, "needs a bound")) << plain.err;
  EXPECT_TRUE(contains(plain.err, "regional")) << plain.err;
}

// Free vertices facing a split segment are deleted by default (Triangle's rule) unless an
// area bound is set; --delete-free deletes them under one too, --keep-free never; the two
// flags together, or --delete-free with bisection, are refused.
TEST_F(RefineCli, DeletesFreeVerticesNearSplitsUnlessKeepFreeOrSized) {
  const std::string input = std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly";
  const auto removed = [&](const std::string& flags) {
    const CommandResult r = meshstep("refine " + input + " --algorithm circumcenter --min-angle 30 --no-output --stats json " + flags);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(json_value(last_line(r.out), "bounds_met"), "true") << r.out;
    return json_number(last_line(r.out), "removed_vertices");
  };
  EXPECT_GT(removed(""), 0.0);
  EXPECT_EQ(removed("--delete-free"), removed(""));
  EXPECT_EQ(removed("--keep-free"), 0.0);
  EXPECT_EQ(removed("--max-area 0.5"), 0.0);
  EXPECT_GT(removed("--max-area 0.5 --delete-free"), 0.0);

  const CommandResult both = meshstep("refine " + input + " --keep-free --delete-free --no-output");
  EXPECT_EQ(both.status, 2) << both.err;
  EXPECT_TRUE(contains(both.err, "contradict")) << both.err;
  const std::string bisect = "refine " + input + " --algorithm lepp-bisection --max-area 0.01 --no-output -q";
  EXPECT_EQ(meshstep(bisect).status, 0);
  const CommandResult asked = meshstep(bisect + " --delete-free");
  EXPECT_EQ(asked.status, 2) << asked.err;
  EXPECT_TRUE(contains(asked.err, "does not go with bisection")) << asked.err;
}

TEST_F(RefineCli, ImproveRemovesVerticesAndKeepsTheBound) {
  const std::string input = write("hole.poly", kSquareWithHole);
  const std::string prefix = dir_.file("improved");
  const CommandResult plain =
      meshstep("refine " + input + " --algorithm circumcenter --min-angle 28 --max-area 0.05 --keep-free --no-output --stats json");
  // --keep-free: every removal is the improvement's (deleting free vertices near splits, the
  // default, leaves it nothing to remove here).
  const CommandResult r = meshstep("refine " + input + " --algorithm improve --min-angle 28 --max-area 0.05 --keep-free -o " +
                                   prefix + " --stats json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = last_line(r.out), before = last_line(plain.out);
  EXPECT_EQ(json_value(json, "bounds_met"), "true") << json;
  EXPECT_GT(json_number(json, "removed_vertices"), 0.0) << json;
  EXPECT_EQ(json_number(json, "steiner") + json_number(json, "removed_vertices"), json_number(before, "steiner"));
  EXPECT_GE(json_number(json, "min_angle"), json_number(before, "min_angle"));
  EXPECT_EQ(json_value(before, "removed_vertices"), "0") << before;
  EXPECT_EQ(meshstep("check " + prefix + " --poly " + input + " -q").status, 0);
  const TriMesh mesh = io::read_mesh(prefix);
  EXPECT_EQ(std::to_string(mesh.points.size()), json_value(json, "vertices"));

  const CommandResult composed = meshstep("refine " + input + " --select offcenter --improve --min-angle 28 "
                                          "--max-area 0.05 --no-output --stats json");
  ASSERT_EQ(composed.status, 0) << composed.err;
  EXPECT_EQ(json_value(last_line(composed.out), "selection"), "offcenter");
  const CommandResult bisection =
      meshstep("refine " + input + " --algorithm lepp-bisection --improve --max-area 0.05 --no-output");
  EXPECT_EQ(bisection.status, 2) << bisection.err;
  EXPECT_TRUE(contains(bisection.err, "--improve")) << bisection.err;
}

TEST_F(RefineCli, DefaultPrefixAndDefaultBound) {
  const std::string input = write("ell.poly", kLShape);
  const CommandResult r = meshstep("refine " + input + " --algorithm offcenter --stats json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_.file("ell.1.node")));
  EXPECT_TRUE(fs::exists(dir_.file("ell.1.ele")));
  // No bound given: the algorithm's default minimum angle, and the progress output says so.
  EXPECT_TRUE(contains(r.err, "default")) << r.err;
  const std::string json = last_line(r.out);
  EXPECT_NEAR(json_number(json, "min_angle_bound"), 20.7, 1e-9) << json;
  EXPECT_GE(json_number(json, "min_angle"), 20.7) << json;
  EXPECT_EQ(json_value(json, "bounds_met"), "true") << json;
  // -q: nothing but the statistics.
  const CommandResult q = meshstep("refine " + input + " -q --no-output --stats json");
  ASSERT_EQ(q.status, 0) << q.err;
  EXPECT_TRUE(q.err.empty()) << q.err;
  EXPECT_EQ(q.out.find('\n'), q.out.size() - 1) << q.out;
}

TEST_F(RefineCli, SizeBoundsEveryEdge) {
  const std::string input = write("hole.poly", kSquareWithHole);
  const std::string prefix = dir_.file("sized");
  const CommandResult r = meshstep("refine " + input + " --size 0.5 -o " + prefix + " --stats json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json_value(last_line(r.out), "bounds_met"), "true") << r.out;
  const TriMesh mesh = io::read_mesh(prefix);
  double longest = 0.0;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const Point& a = mesh.points[t[i]];
      const Point& b = mesh.points[t[(i + 1) % 3]];
      longest = std::max(longest, std::hypot(a.x - b.x, a.y - b.y));
    }
  EXPECT_LE(longest, 0.5 * (1 + 1e-9));
  EXPECT_GT(mesh.triangles.size(), 64u);  // the 12 square units need many small triangles
}

TEST_F(RefineCli, UnknownAlgorithmIsAUsageErrorListingTheNames) {
  const std::string input = write("ell.poly", kLShape);
  const CommandResult r = meshstep("refine " + input + " --algorithm chew3000");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "meshstep: error:")) << r.err;
  EXPECT_TRUE(contains(r.err, "circumcenter")) << r.err;
  EXPECT_TRUE(contains(r.err, "offcenter")) << r.err;
  EXPECT_FALSE(fs::exists(dir_.file("ell.1.node")));
  EXPECT_EQ(meshstep("refine " + input + " --select centroid").status, 2);
  EXPECT_EQ(meshstep("refine " + input + " --ds octree").status, 2);
  EXPECT_EQ(meshstep("refine " + input + " --max-area -1").status, 2);
  EXPECT_EQ(meshstep("refine " + input + " --max-steiner 0").status, 2);
  EXPECT_EQ(meshstep("refine " + input + " --size -1").status, 2);
  EXPECT_EQ(meshstep("refine").status, 2);
}

// An option out of its range is a usage error (exit 2), said alone: no warning about the
// angle, no progress line, no output before it.
TEST_F(RefineCli, OutOfRangeAngleIsAUsageErrorSaidAlone) {
  const std::string input = write("ell.poly", kLShape);
  const CommandResult r = meshstep("refine " + input + " --min-angle 70 -v --record " + dir_.file("x.mslog"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("meshstep: error:", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line only:\n" << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(contains(r.err, "minimum angle")) << r.err;
  EXPECT_TRUE(contains(r.err, "60")) << r.err;
  // Nothing is left behind: no mesh, no log, no partial log.
  EXPECT_FALSE(fs::exists(dir_.file("ell.1.node")));
  EXPECT_FALSE(fs::exists(dir_.file("x.mslog")));
  EXPECT_FALSE(fs::exists(dir_.file("x.mslog.partial")));
  const CommandResult m = meshstep("refine " + input + " --max-angle 50");
  EXPECT_EQ(m.status, 2);
  EXPECT_TRUE(contains(m.err, "maximum angle")) << m.err;
}

TEST_F(RefineCli, MissingInputNamesThePath) {
  const std::string missing = dir_.file("nowhere.poly");
  const CommandResult r = meshstep("refine " + missing);
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "meshstep: error: " + missing)) << r.err;
}

// --size GRID.asc: an ESRI ASCII grid of sizes, fine on the west half of the L and coarse
// on the east; every edge meets the cell under its triangle's centroid. Bad grids are
// input errors with the file and line, and nothing is written.
TEST_F(RefineCli, SizeGridBoundsEdgesCellByCell) {
  const std::string input = write("ell.poly", kLShape);
  const std::string grid = write("sizes.asc",
                                 "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1.5\n"
                                 "NODATA_value -9999\n0.1 0.5\n0.1 0.5\n");
  // 1.5 x 1.5 cells: x in [0, 1.5) is 0.1, [1.5, 3] is 0.5; the L spans [0, 3] x [0, 3].
  const std::string prefix = dir_.file("graded");
  const CommandResult r = meshstep("refine " + input + " --size " + grid + " -o " + prefix + " --stats json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json_value(last_line(r.out), "bounds_met"), "true");
  const TriMesh m = io::read_mesh(prefix);
  std::size_t fine = 0, coarse = 0;
  for (const auto& t : m.triangles) {
    const Point &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    const double longest = std::max({std::hypot(a.x - b.x, a.y - b.y), std::hypot(b.x - c.x, b.y - c.y),
                                     std::hypot(c.x - a.x, c.y - a.y)});
    const double cx = (a.x + b.x + c.x) / 3.0;
    ASSERT_LE(longest, (cx < 1.5 ? 0.1 : 0.5) * (1 + 1e-12)) << "centroid x " << cx;
    (cx < 1.5 ? fine : coarse) += 1;
  }
  EXPECT_GT(fine, 10 * coarse);

  const std::string bad = write("bad.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3 x\n");
  const CommandResult e = meshstep("refine " + input + " --size " + bad + " -o " + dir_.file("never"));
  EXPECT_EQ(e.status, 1);
  EXPECT_TRUE(contains(e.err, "bad.asc:7:")) << e.err;
  EXPECT_FALSE(fs::exists(dir_.file("never.node")));
  const CommandResult short_grid = meshstep("refine " + input + " --size " +
                                            write("short.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n"));
  EXPECT_EQ(short_grid.status, 1);
  EXPECT_TRUE(contains(short_grid.err, "short.asc:2: 2 x 2 = 4 values, but the file can hold at most 3")) << short_grid.err;
  const CommandResult missing = meshstep("refine " + input + " --size " + dir_.file("absent.asc"));
  EXPECT_EQ(missing.status, 1);
  EXPECT_TRUE(contains(missing.err, "absent.asc")) << missing.err;
}

// A mesh prefix is re-refined (Triangle's -r): PREFIX.area bounds the triangles it names,
// the next prefix number is the default output, and the result covers the same domain.
TEST_F(RefineCli, ReRefinesAMeshWithItsAreaFile) {
  const std::string input = write("hole.poly", kSquareWithHole);
  const std::string prefix = dir_.file("holemesh.1");
  ASSERT_EQ(meshstep("triangulate " + input + " -q -o " + prefix).status, 0);
  const TriMesh old = io::read_mesh(prefix);
  std::string area = std::to_string(old.triangles.size()) + "\n";
  for (std::size_t t = 0; t < old.triangles.size(); ++t)
    area += std::to_string(t + old.first_index) + " " + (t == 0 ? "0.001" : "-1") + "\n";
  write("holemesh.1.area", area);
  const CommandResult r = meshstep("refine " + prefix + " --min-angle 25 --stats json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "re-refinement")) << r.err;
  const std::string json = last_line(r.out);
  EXPECT_EQ(json_value(json, "bounds_met"), "true") << json;
  const TriMesh m = io::read_mesh(dir_.file("holemesh.2"));
  // The first old triangle (area bound 0.001) is now covered by many small triangles.
  std::size_t small = 0;
  for (const auto& t : m.triangles) {
    const Point &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    small += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) <= 0.001;
  }
  EXPECT_GT(small, 50u);
  EXPECT_EQ(meshstep("check " + dir_.file("holemesh.2") + " --poly " + input + " -q").status, 0);
  // The .area file is a bound of its own: the area-only algorithms take it without
  // --max-area (as Triangle's -r -a), and every triangle it bounds comes out small.
  for (const char* algorithm : {"midpoint-area", "lepp-bisection"}) {
    SCOPED_TRACE(algorithm);
    const std::string out = dir_.file(std::string("by_area_") + algorithm);
    const CommandResult a = meshstep("refine " + prefix + " --algorithm " + algorithm + " -o " + out + " --stats json");
    ASSERT_EQ(a.status, 0) << a.err;
    EXPECT_EQ(json_value(last_line(a.out), "bounds_met"), "true") << a.out;
    EXPECT_GT(json_number(last_line(a.out), "steiner"), 10.0) << a.out;
  }
  std::filesystem::remove(dir_.file("holemesh.1.area"));
  const CommandResult no_bound = meshstep("refine " + prefix + " --algorithm midpoint-area --no-output");
  EXPECT_EQ(no_bound.status, 2) << no_bound.err;
  EXPECT_TRUE(contains(no_bound.err, "needs a bound")) << no_bound.err;
  // Without the mesh files, a name with no known extension is an unknown file type.
  const CommandResult u = meshstep("refine " + dir_.file("nothing"));
  EXPECT_EQ(u.status, 1);
  EXPECT_FALSE(contains(u.err, "re-refinement")) << u.err;
}

TEST_F(RefineCli, MaxSteinerStopsAtTheCap) {
  const std::string input = write("hole.poly", kSquareWithHole);
  const CommandResult r = meshstep("refine " + input + " --min-angle 33 --max-area 0.01 --max-steiner 5 "
                                   "--no-output --stats json");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = last_line(r.out);
  EXPECT_EQ(json_value(json, "stopped_by_cap"), "true") << json;
  EXPECT_EQ(json_value(json, "bounds_met"), "false") << json;
  EXPECT_LE(json_number(json, "steiner"), 5.0) << json;
  EXPECT_GT(json_number(json, "bad_triangles"), 0.0) << json;
  EXPECT_TRUE(contains(r.err, "warning")) << r.err;
  EXPECT_TRUE(contains(r.err, "--max-steiner")) << r.err;
  EXPECT_TRUE(contains(r.out, "bounds missed by")) << r.out;
  EXPECT_FALSE(fs::exists(dir_.file("hole.1.node")));  // --no-output
}

// Longest-edge midpoints against an angle bound: on A.poly at 30 degrees they never finish
// (the smallest angle falls as the vertices pile up). Without a cap of the user's the run gets
// one and says so up front; with one, or with an area bound only, nothing is added.
TEST_F(RefineCli, MidpointsAgainstAnAngleBoundGetACap) {
  const fs::path a = testing::shared_data() / "pslg" / "A.poly";
  if (!fs::exists(a)) GTEST_SKIP() << a << " is absent: skipped";
  const std::string midpoints = "refine " + a.string() + " --algorithm midpoint-area --no-output --stats json";
  const CommandResult r = meshstep(midpoints + " --min-angle 30");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = last_line(r.out);
  EXPECT_EQ(json_value(json, "stopped_by_cap"), "true") << json;
  EXPECT_EQ(json_number(json, "steiner"), 100'000.0 + 100.0 * json_number(json, "input_vertices")) << json;
  EXPECT_TRUE(contains(r.err, "longest-edge midpoints")) << r.err;
  EXPECT_TRUE(contains(r.err, "--max-steiner")) << r.err;

  const CommandResult capped = meshstep(midpoints + " --min-angle 30 --max-steiner 500");
  ASSERT_EQ(capped.status, 0) << capped.err;
  EXPECT_EQ(json_number(last_line(capped.out), "steiner"), 500.0);
  EXPECT_FALSE(contains(capped.err, "longest-edge midpoints")) << capped.err;
  const CommandResult area = meshstep(midpoints + " --max-area 0.01");
  ASSERT_EQ(area.status, 0) << area.err;
  EXPECT_EQ(json_value(last_line(area.out), "bounds_met"), "true");
  EXPECT_FALSE(contains(area.err, "longest-edge midpoints")) << area.err;
}

TEST_F(RefineCli, RecordedRunVerifies) {
  const std::string input = write("hole.poly", kSquareWithHole);
  const std::string log = dir_.file("hole.mslog");
  const std::string prefix = dir_.file("hole_q");
  const CommandResult r =
      meshstep("refine " + input + " --algorithm offcenter --min-angle 30 --record " + log + " -o " + prefix);
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(fs::exists(log));
  EXPECT_FALSE(fs::exists(log + ".partial"));
  const CommandResult v = meshstep("log verify " + log);
  EXPECT_EQ(v.status, 0) << v.out << v.err;
  const CommandResult info = meshstep("log info " + log);
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_TRUE(contains(info.out, "offcenter")) << info.out;
  EXPECT_TRUE(contains(info.out, "min_angle=30")) << info.out;
  // The log's last step is the mesh that was written.
  const std::string replayed = dir_.file("replayed");
  ASSERT_EQ(meshstep("log mesh " + log + " --step -1 -o " + replayed).status, 0);
  const TriMesh a = io::read_mesh(prefix), b = io::read_mesh(replayed);
  EXPECT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(a.triangles.size(), b.triangles.size());
}

TEST_F(RefineCli, ListShowsEveryPart) {
  const CommandResult r = meshstep("list");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* name : {"circumcenter", "offcenter", "tds", "dcel", "flip", "cavity", "min-angle", ".poly",
                           "Algorithms", "Data structures"})
    EXPECT_TRUE(contains(r.out, name)) << name << " in " << r.out;
  // Every format of the table (io/formats.hpp), with its kind and what meshstep does with it.
  for (const char* name : {".tif", "grid, R:", ".mslog", "log, RW:", ".stl", "surface, RW:", ".edge", "mesh, W:"})
    EXPECT_TRUE(contains(r.out, name)) << name << " in " << r.out;
  const CommandResult j = meshstep("list --json");
  ASSERT_EQ(j.status, 0) << j.err;
  const std::string json = last_line(j.out);
  EXPECT_EQ(j.out, json + "\n");  // one line
  ASSERT_EQ(json.front(), '{');
  ASSERT_EQ(json.back(), '}');
  for (const char* part : {"\"algorithms\":[", "\"selections\":[", "\"insertions\":[", "\"criteria\":[",
                           "\"data_structures\":[", "\"file_formats\":[", "\"name\":\"offcenter\"",
                           "\"name\":\"dcel\"", "\"default_min_angle\":"})
    EXPECT_TRUE(contains(json, part)) << part << " in " << json;
}

// The help of every option made from the registry lists exactly the words it accepts: the
// --select line named two selections of five (issue 26).
TEST_F(RefineCli, HelpListsExactlyTheAcceptedWords) {
  const CommandResult help = meshstep("refine --help");
  ASSERT_EQ(help.status, 0) << help.err;
  for (const char* option : {"--select", "--algorithm"}) {
    const ParameterInfo* parameter = find_parameter(std::string(option).substr(2));
    ASSERT_NE(parameter, nullptr);
    const std::size_t at = help.out.find(option);
    ASSERT_NE(at, std::string::npos) << option;
    const std::size_t colon = help.out.find(": ", at);
    const std::size_t end = help.out.find('\n', colon);
    std::vector<std::string> listed;
    std::string words = help.out.substr(colon + 2, end - colon - 2);
    for (std::size_t from = 0; from <= words.size();) {
      const std::size_t comma = std::min(words.find(", ", from), words.size());
      listed.push_back(words.substr(from, comma - from));
      from = comma + 2;
    }
    EXPECT_EQ(listed, choices(*parameter)) << help.out.substr(at, end - at);
    for (const std::string& word : listed) {  // and each of them is taken
      const std::string args = "refine " + dir_.file("none.poly") + " " + option + " " + word + " --no-output -q";
      const CommandResult r = meshstep(args);
      EXPECT_FALSE(contains(r.err, "not in")) << args << ": " << r.err;
    }
  }
}

TEST_F(RefineCli, HelpExplains) {
  const CommandResult r = meshstep("refine --help");
  EXPECT_EQ(r.status, 0);
  for (const char* option : {"--algorithm", "--min-angle", "--max-area", "--size", "--select", "--record",
                             "--stats", "assets/examples/plate.poly"})
    EXPECT_TRUE(contains(r.out, option)) << option;
  const CommandResult top = meshstep("--help");
  EXPECT_TRUE(contains(top.out, "refine")) << top.out;
  EXPECT_TRUE(contains(top.out, "list")) << top.out;
}

// A bound no refinement reaches (59 degrees on plate.poly): a warning before it starts, a
// stop at the memory budget (here 40 MB, about 260,000 triangles) with nothing written and
// exit 1; with --write-partial, the valid mesh reached; a budget that is not a size is a
// usage error.
TEST_F(RefineCli, AnUnreachableBoundStopsAtTheMemoryBudget) {
  const std::string plate = std::string(MESHSTEP_ASSETS) + "/examples/plate.poly";
  const std::string out = dir_.file("p59");
  const CommandResult r = meshstep("refine " + plate + " --min-angle 59 --max-memory 40M -o " + out);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "--min-angle 59 is above 34 degrees, past which offcenter refinement is not known to end"))
      << r.err;
  // Each algorithm by its own record: circumcenters end in practice to 33 degrees.
  const CommandResult circumcenter =
      meshstep("refine " + plate + " --algorithm circumcenter --min-angle 33.5 --max-steiner 10 --no-output");
  EXPECT_TRUE(contains(circumcenter.err, "above 33 degrees, past which circumcenter refinement is not known to end: "
                                         "it stops at your cap"))
      << circumcenter.err;
  EXPECT_FALSE(contains(meshstep("refine " + plate + " --min-angle 33.5 --max-steiner 10 --no-output").err, "not known"));
  EXPECT_TRUE(contains(r.err, "stopped at the memory budget (40 MB, about 262144 triangles")) << r.err;
  EXPECT_TRUE(contains(r.err, "nothing written")) << r.err;
  EXPECT_FALSE(fs::exists(out + ".node"));
  EXPECT_FALSE(fs::exists(out + ".ele"));

  const CommandResult partial = meshstep("refine " + plate + " --min-angle 59 --max-memory 40M --write-partial -o " + out);
  ASSERT_EQ(partial.status, 0) << partial.err;
  EXPECT_TRUE(contains(partial.err, "written as it is (--write-partial)")) << partial.err;
  const CommandResult check = meshstep("check " + out + " --poly " + plate);
  EXPECT_EQ(check.status, 0) << check.out << check.err;
  EXPECT_TRUE(contains(check.out, "ok (")) << check.out;

  const CommandResult bad = meshstep("refine " + plate + " --min-angle 30 --max-memory lots");
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_TRUE(contains(bad.err, "--max-memory lots: expected a size")) << bad.err;
}

// Two segments meeting at about 10 degrees: a bound above it is warned of before the run,
// naming the segments and the vertex (1-based, as the file numbers them); a bound below it
// is not.
TEST_F(RefineCli, WarnsOfAnInputAngleBelowTheBound) {
  const std::string wedge = write("wedge.poly", "3 2 0 0\n1 0 0\n2 10 0\n3 10 1.7633\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n");
  const CommandResult above = meshstep("refine " + wedge + " --min-angle 20 -o " + dir_.file("w20"));
  EXPECT_EQ(above.status, 0) << above.err;
  EXPECT_TRUE(contains(above.err, "segments 1 and 3 meet at vertex 1 at 10 degrees, below --min-angle 20")) << above.err;
  const CommandResult below = meshstep("refine " + wedge + " --min-angle 9 -o " + dir_.file("w9"));
  EXPECT_EQ(below.status, 0) << below.err;
  EXPECT_FALSE(contains(below.err, "meet at vertex")) << below.err;
}

}  // namespace
}  // namespace meshstep
