// `meshstep log mesh LOG --step -1` writes the very files of the run that wrote LOG, byte
// for byte: vertex markers and attributes, segment markers, the boundary that carving or
// the hull made, regional attributes and area bounds (.area), holes and regions, for
// triangulate and every refinement algorithm, on a PSLG that has all of these and on a
// plain point set.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::slurp;

// A square with a square hole, two interior segments crossing each other (a Steiner
// vertex where they meet), a loose vertex, two attributes and a marker a vertex, segment
// markers, two regions (the right one with an area bound).
constexpr const char* kEverything = R"(13 2 2 1
1 0 0 0.5 -1 7
2 8 0 1.5 -2 7
3 8 6 2.5 -3 7
4 0 6 3.5 -4 7
5 3 2 4 4 9
6 5 2 5 5 9
7 5 4 6 6 9
8 3 4 7 7 9
9 1 1 8 8 0
10 7 5 9 9 0
11 1 5 10 10 0
12 7 1 11 11 0
13 6.5 3 12 12 0
10 1
1 1 2 3
2 2 3 3
3 3 4 3
4 4 1 3
5 5 6 4
6 6 7 4
7 7 8 4
8 8 5 4
9 9 10 5
10 11 12 6
1
1 4 3
2
1 1 3 10 -1
2 7.5 3 20 0.5
)";

// A point set: its hull is the boundary (marker 1), no segments of its own.
constexpr const char* kPoints = R"(12 2 1 0
0 0 0 1
1 4 0 2
2 4 3 3
3 0 3 4
4 1 1 5
5 3 1 6
6 2 2 7
7 1 2 8
8 3 2.5 9
9 2 0.5 10
10 0.5 2.7 11
11 3.6 1.4 12
)";

class LogMeshFiles : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    std::ofstream(dir_.file("everything.poly")) << kEverything;
    std::ofstream(dir_.file("points.node")) << kPoints;
  }
  CommandResult meshstep(const std::string& args) const { return testing::run_meshstep(args, dir_.path()); }
  // "{E}" and "{P}" in a parameter stand for the two inputs.
  std::string expand(std::string args) const {
    for (const auto& [key, file] : {std::pair{"{E}", "everything.poly"}, std::pair{"{P}", "points.node"}})
      for (std::size_t at; (at = args.find(key)) != std::string::npos;) args.replace(at, 3, dir_.file(file));
    return args;
  }
  testing::TempDir dir_{"meshstep_log_mesh_files_"};
};

TEST_P(LogMeshFiles, AreTheRunsOwnFiles) {
  const std::string run = dir_.file("run"), log = dir_.file("run.mslog"), replayed = dir_.file("replayed");
  const CommandResult r = meshstep(expand(GetParam()) + " --record " + log + " -o " + run + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const CommandResult m = meshstep("log mesh " + log + " --step -1 -o " + replayed);
  ASSERT_EQ(m.status, 0) << m.err;
  for (const std::string ext : {".node", ".ele", ".poly", ".area"}) {
    ASSERT_EQ(fs::exists(run + ext), fs::exists(replayed + ext)) << ext;
    if (fs::exists(run + ext)) {
      EXPECT_EQ(slurp(replayed + ext), slurp(run + ext)) << ext << " differs";
    }
  }
  // What the test is about is there to compare: markers, attributes, regions.
  const std::string node = slurp(run + ".node");
  if (std::string(GetParam()).find("{E}") != std::string::npos) {
    EXPECT_EQ(node.substr(0, node.find('\n')).substr(node.find(' ')), " 2 2 1") << node.substr(0, 40);
    EXPECT_TRUE(fs::exists(run + ".area"));
  } else {
    EXPECT_EQ(node.substr(0, node.find('\n')).substr(node.find(' ')), " 2 1 0") << node.substr(0, 40);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Runs, LogMeshFiles,
    ::testing::Values("triangulate {E}", "triangulate {E} --ds dcel --insertion cavity", "triangulate {P}",
                      "triangulate {E} --convex-hull", "refine {E} --min-angle 30",
                      "refine {E} --algorithm circumcenter --min-angle 28 --ds dcel",
                      "refine {E} --algorithm offcenter --min-angle 30 --encroachment lens",
                      "refine {E} --algorithm lepp-midpoint --min-angle 25",
                      "refine {E} --algorithm lepp-centroid --min-angle 28 --insertion cavity",
                      "refine {E} --algorithm lepp-bisection --max-area 0.5",
                      "refine {E} --algorithm midpoint-area --max-area 0.5",
                      "refine {E} --algorithm lepp-aspect", "refine {E} --algorithm improve --min-angle 25",
                      "refine {E} --algorithm combined", "refine {P} --min-angle 30",
                      "refine {P} --algorithm lepp-bisection --max-area 0.2"));

}  // namespace
}  // namespace meshstep
