// The `meshstep` command-line contract: exit statuses, error format, outputs, --stats json.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <string>

#include "meshstep/io/triangle_io.hpp"
#include "run_cli.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;

using testing::CommandResult;

// Each test in a folder of its own, named after the process (run_cli.hpp: CliTest).
class Cli : public testing::CliTest {};

constexpr const char* kSquareWithHole =
    "# square with a square hole\n"
    "8 2 0 1\n"
    "1 0 0 1\n2 4 0 1\n3 4 4 1\n4 0 4 1\n5 1 1 2\n6 3 1 2\n7 3 3 2\n8 1 3 2\n"
    "8 1\n"
    "1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n"
    "1\n1 2 2\n";

TEST_F(Cli, HelpExitsZeroAndExplains) {
  CommandResult r = meshstep("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("triangulate"), std::string::npos);
  EXPECT_NE(r.out.find("Exit status"), std::string::npos);
  r = meshstep("triangulate --help");
  EXPECT_EQ(r.status, 0);
  for (const char* option : {"--ds", "--insertion", "--convex-hull", "--stats", "--no-output"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  EXPECT_EQ(meshstep("check --help").status, 0);
}

TEST_F(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(meshstep("").status, 2);
  EXPECT_EQ(meshstep("frobnicate").status, 2);
  EXPECT_EQ(meshstep("triangulate").status, 2);
  const CommandResult r = meshstep("triangulate x.poly --ds octree");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("meshstep: error:"), std::string::npos) << r.err;
}

TEST_F(Cli, TriangulateWritesTriangleFilesWithDefaultPrefix) {
  const fs::path in = write("sq.poly", kSquareWithHole);
  const CommandResult r = meshstep(in.string());  // no subcommand: usage
  EXPECT_EQ(r.status, 2);
  const CommandResult t = meshstep("triangulate " + in.string());
  ASSERT_EQ(t.status, 0) << t.err;
  for (const char* ext : {".node", ".ele", ".poly"}) EXPECT_TRUE(fs::exists(file(std::string("sq.1") + ext)));
  const TriMesh m = io::read_mesh(file("sq.1"));
  EXPECT_EQ(m.triangles.size(), 8u);
  EXPECT_EQ(m.first_index, 1);  // numbering follows the input
  // Triangulating the output again gives the next number, as Triangle does.
  EXPECT_EQ(meshstep("triangulate " + file("sq.1.node") + " -q").status, 0);
  EXPECT_TRUE(fs::exists(file("sq.2.ele")));
  const CommandResult c = meshstep("check " + file("sq.1") + " --poly " + in.string());
  EXPECT_EQ(c.status, 0) << c.err;
}

TEST_F(Cli, StatsJsonIsTheLastLine) {
  const fs::path in = write("sq.poly", kSquareWithHole);
  for (const char* config : {"--ds tds --insertion flip", "--ds dcel --insertion cavity"}) {
    const CommandResult r = meshstep("triangulate " + in.string() + " --no-output --stats json " + config);
    ASSERT_EQ(r.status, 0) << r.err;
    std::string last = r.out.substr(0, r.out.size() - 1);
    last = last.substr(last.find_last_of('\n') + 1);
    ASSERT_EQ(last.front(), '{');
    ASSERT_EQ(last.back(), '}');
    for (const char* key : {"\"vertices\":8", "\"triangles\":8", "\"input_vertices\":8", "\"steiner\":0",
                            "\"min_angle\":", "\"max_angle\":", "\"ms\":{\"read\":", "\"triangulate\":",
                            "\"write\":"})
      EXPECT_NE(last.find(key), std::string::npos) << key << " in " << last;
  }
  EXPECT_FALSE(fs::exists(file("sq.1.node")));  // --no-output
}

TEST_F(Cli, CheckFailsOnABrokenMesh) {
  write("bad.node", "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n");
  write("bad.ele", "2 3 0\n0 0 1 2\n1 0 3 2\n");  // second triangle is clockwise
  const CommandResult r = meshstep("check " + file("bad"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("clockwise"), std::string::npos) << r.err;
}

// Every malformed input: exit 1, one "meshstep: error: FILE:LINE: message" line, no crash,
// and no output files left behind.
TEST_F(Cli, MalformedInputsGiveFileLineErrors) {
  const std::array<std::pair<const char*, std::string>, 9> cases{{
      {"empty.node", ""},
      {"truncated.node", "3 2 0 0\n1 0 0\n2 1 0\n"},
      {"word.node", "3 2 0 0\n1 0 0\n2 one 0\n3 0 1\n"},
      {"nan.node", "3 2 0 0\n1 0 0\n2 nan 0\n3 0 1\n"},
      {"inf.node", "3 2 0 0\n1 0 0\n2 1 inf\n3 0 1\n"},
      {"absurd.node", "999999999999 2 0 0\n1 0 0\n"},
      {"range.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 9\n0\n"},
      {"binary.node", std::string("3 2 0 0\n\x01\x02\xff\x00garbage", 20)},  // NUL included
      {"collinear.node", "3 2 0 0\n1 0 0\n2 1 1\n3 2 2\n"},
  }};
  for (const auto& [name, text] : cases) {
    const fs::path in = write(name, text);
    const CommandResult r = meshstep("triangulate " + in.string() + " -o " + file("out"));
    EXPECT_EQ(r.status, 1) << name << ": " << r.err;
    EXPECT_EQ(r.err.rfind("meshstep: error: " + in.string() + ":", 0), 0u) << name << ": " << r.err;
    EXPECT_FALSE(fs::exists(file("out.node"))) << name;
  }
  const CommandResult missing = meshstep("triangulate " + file("nope.poly"));
  EXPECT_EQ(missing.status, 1);
}

}  // namespace
}  // namespace meshstep
