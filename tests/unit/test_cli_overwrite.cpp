// Issue 31: no command writes over one of its own inputs, nor writes two outputs to one file.
// Each case is refused before any work, with the usage status, the clash named, and the
// input left as it was, byte for byte. The same file is found under its own name, under
// another spelling of the path, and through a hard link or a symlink.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_meshstep;
using testing::slurp;
using testing::TempDir;

constexpr const char* kLShape =
    "6 2 0 1\n"
    "1 0 0 1\n2 2 0 1\n3 2 1 1\n4 1 1 1\n5 1 2 1\n6 0 2 1\n"
    "6 1\n"
    "1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 5 1\n5 5 6 1\n6 6 1 1\n"
    "0\n";

constexpr const char* kTetrahedron =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

// A 9 x 9 grid of a smooth hill.
std::string hill_grid() {
  std::string text = "ncols 9\nnrows 9\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -9999\n";
  for (int r = 0; r < 9; ++r) {
    for (int c = 0; c < 9; ++c) text += std::to_string((r - 4) * (r - 4) + (c - 4) * (c - 4)) + " ";
    text += "\n";
  }
  return text;
}

class CliOverwrite : public ::testing::Test {
 protected:
  // Runs meshstep with `args` in the test's folder and expects the refusal: status 2,
  // "would overwrite the input" (or "would write the same file"), and `input` unchanged.
  void expect_refused(const std::string& args, const std::string& input, const std::string& why) {
    const std::string before = slurp(input);
    ASSERT_FALSE(before.empty()) << input;
    const CommandResult run = run_in_dir(args);
    EXPECT_EQ(run.status, 2) << args << "\n" << run.err;
    EXPECT_NE(run.err.find(why), std::string::npos) << args << "\n" << run.err;
    EXPECT_EQ(run.err.find("internal"), std::string::npos) << run.err;
    EXPECT_EQ(slurp(input), before) << args << ": the input changed";
  }

  // meshstep run from the test's folder, so that relative names are in it.
  CommandResult run_in_dir(const std::string& args) {
    const fs::path here = fs::current_path();
    fs::current_path(dir_.path());
    CommandResult r = run_meshstep(args, dir_.path());
    fs::current_path(here);
    return r;
  }

  std::string file(const std::string& name) const { return dir_.file(name); }
  std::string write(const std::string& name, const std::string& text) const { return dir_.write(name, text); }
  std::string hard_link(const std::string& target, const std::string& name) const {
    fs::create_hard_link(file(target), file(name));
    return file(name);
  }

  // A recorded run of the L-shaped input: l.mslog.
  std::string record_log() {
    write("L.poly", kLShape);
    const CommandResult r = run_in_dir("triangulate L.poly --no-output -q --record l.mslog");
    EXPECT_EQ(r.status, 0) << r.err;
    return file("l.mslog");
  }

  TempDir dir_{"meshstep_overwrite_"};
};

constexpr const char* kOverwrites = "would overwrite the input";
constexpr const char* kSameOutput = "would write the same file";

TEST_F(CliOverwrite, TriangulateRefusesAPrefixThatWritesTheInput) {
  const std::string input = write("L.poly", kLShape);
  expect_refused("triangulate L.poly -o L", input, kOverwrites);
  expect_refused("triangulate L.poly -o " + file("L"), input, kOverwrites);  // absolute
  fs::create_directory(file("sub"));
  expect_refused("triangulate ./L.poly -o sub/../L", input, kOverwrites);  // spelt otherwise
  hard_link("L.poly", "H.poly");
  expect_refused("triangulate L.poly -o H", input, kOverwrites);
  fs::create_symlink("L.poly", file("S.node"));
  expect_refused("triangulate L.poly -o S", input, kOverwrites);
  expect_refused("triangulate L.poly -o out --record L.poly", input, kOverwrites);
  // The message says what clashes and what to do.
  const CommandResult r = run_in_dir("triangulate L.poly -o L");
  EXPECT_NE(r.err.find("meshstep: error: -o L would overwrite the input L.poly; choose another output prefix"),
            std::string::npos)
      << r.err;
}

TEST_F(CliOverwrite, TriangulateRefusesTwoOutputsThatAreOneFile) {
  const std::string input = write("L.poly", kLShape);
  expect_refused("triangulate L.poly -o out --record out.node", input, kSameOutput);
  EXPECT_FALSE(fs::exists(file("out.node")));
  EXPECT_FALSE(fs::exists(file("out.ele")));
  // Elsewhere the same options work.
  EXPECT_EQ(run_in_dir("triangulate L.poly -o out --record out.mslog -q").status, 0);
}

TEST_F(CliOverwrite, RefineRefusesItsInputsAsOutputs) {
  const std::string input = write("L.poly", kLShape);
  expect_refused("refine L.poly --min-angle 25 -o L", input, kOverwrites);
  expect_refused("refine L.poly --min-angle 25 -o ./L", input, kOverwrites);
  hard_link("L.poly", "H.poly");
  expect_refused("refine L.poly --min-angle 25 -o H", input, kOverwrites);
  expect_refused("refine L.poly --min-angle 25 -o out --record ./L.poly", input, kOverwrites);
  expect_refused("refine L.poly --min-angle 25 -o out --record out.ele", input, kSameOutput);
  // A size grid is an input too.
  const std::string sizes = write("sizes.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 1\n1 1\n");
  expect_refused("refine L.poly --size sizes.asc -o out --record sizes.asc", sizes, kOverwrites);
  // A mesh refined again into its own prefix.
  ASSERT_EQ(run_in_dir("refine L.poly --min-angle 20 -q -o box.1").status, 0);
  expect_refused("refine box.1 --min-angle 25 -o box.1", file("box.1.node"), kOverwrites);
  expect_refused("refine box.1 --min-angle 25 -o ./box.1", file("box.1.ele"), kOverwrites);
}

TEST_F(CliOverwrite, RefineRefusesTheIssuesCaseAndTheNodeBesideAPoly) {
  // The issue: refine /tmp/L.poly -o /tmp/L replaced the input with its segments-only .poly.
  const std::string input = write("L.poly", kLShape);
  expect_refused("refine " + input + " -o " + file("L"), input, kOverwrites);
  // A .poly without vertices reads the .node beside it: that file is an input as well.
  write("V.node", "6 2 0 0\n1 0 0\n2 2 0\n3 2 1\n4 1 1\n5 1 2\n6 0 2\n");
  const std::string poly = write("V.poly", "0 2 0 0\n6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n0\n");
  expect_refused("refine V.poly --min-angle 25 -o out --record V.node", file("V.node"), kOverwrites);
  (void)poly;
}

TEST_F(CliOverwrite, RefineOfASurfaceRefusesItsInput) {
  const std::string input = write("t.off", kTetrahedron);
  expect_refused("refine t.off --algorithm lepp-bisection --size 0.5 -o t.off", input, kOverwrites);
  expect_refused("refine t.off --algorithm lepp-bisection --size 0.5 -o ./t.off", input, kOverwrites);
  hard_link("t.off", "h.off");
  expect_refused("refine t.off --algorithm lepp-bisection --size 0.5 -o h.off", input, kOverwrites);
  expect_refused("refine t.off --algorithm lepp-bisection --size 0.5 -o out.off --record out.off", input,
                 kSameOutput);
}

TEST_F(CliOverwrite, LogMeshRefusesAPrefixThatWritesTheLog) {
  const std::string log = record_log();
  hard_link("l.mslog", "m.node");
  expect_refused("log mesh l.mslog --step -1 -o m", log, kOverwrites);
  expect_refused("log mesh l.mslog --step -1 -o ./m", log, kOverwrites);
}

TEST_F(CliOverwrite, RenderRefusesAPictureThatIsItsInput) {
  const std::string log = record_log();
  hard_link("l.mslog", "pic.svg");
  expect_refused("render l.mslog -o pic.svg", log, kOverwrites);
  fs::create_symlink("l.mslog", file("link.png"));
  expect_refused("render l.mslog -o ./link.png", log, kOverwrites);
  // A log named as a picture, drawn to its default name (its own).
  fs::copy_file(log, file("run.png"));
  expect_refused("render run.png", file("run.png"), kOverwrites);
}

TEST_F(CliOverwrite, ExportRefusesAVideoOrFrameThatIsTheLog) {
  const std::string log = record_log();
  hard_link("l.mslog", "v.mp4");
  expect_refused("export l.mslog --video v.mp4", log, kOverwrites);
  fs::create_directory(file("frames"));
  fs::create_hard_link(log, file("frames/frame_000000.png"));
  expect_refused("export l.mslog --frames frames", log, kOverwrites);
  expect_refused("export l.mslog --frames l.mslog", log, kOverwrites);
}

TEST_F(CliOverwrite, TerrainRefusesOutputsThatAreTheGrid) {
  const std::string grid = write("g.asc", hill_grid());
  hard_link("g.asc", "g.obj");
  expect_refused("terrain g.asc --max-error 0.5 -o g.obj", grid, kOverwrites);
  hard_link("g.asc", "t.ele");
  expect_refused("terrain g.asc --max-error 0.5 -o t.node", grid, kOverwrites);
  expect_refused("terrain g.asc --max-error 0.5 --record ./g.asc", grid, kOverwrites);
  expect_refused("terrain g.asc --max-error 0.5 -o tin.obj --record tin.obj", grid, kSameOutput);
  // A tile of the run that is the grid.
  hard_link("g.asc", "tiles.r0-c1.obj");
  expect_refused("terrain g.asc --max-error 0.5 --tile 5 -o tiles.obj", grid, kOverwrites);
  expect_refused("terrain g.asc --max-error 0.5 --tile 5 --tile-index 0,1 -o ./tiles.obj", grid, kOverwrites);
}

TEST_F(CliOverwrite, TerrainJoinRefusesAnOutputThatIsATile) {
  write("g.asc", hill_grid());
  ASSERT_EQ(run_in_dir("terrain g.asc --max-error 0.5 --tile 5 -q -o t.ply").status, 0);
  const std::string tiles = "t.r0-c0.ply t.r0-c1.ply t.r1-c0.ply t.r1-c1.ply";
  expect_refused("terrain-join " + tiles + " -o t.r1-c1.ply", file("t.r1-c1.ply"), kOverwrites);
  expect_refused("terrain-join " + tiles + " -o ./t.r0-c0.ply", file("t.r0-c0.ply"), kOverwrites);
  EXPECT_EQ(run_in_dir("terrain-join " + tiles + " -q -o joined.ply").status, 0);
}

}  // namespace
}  // namespace meshstep
