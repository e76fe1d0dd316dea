// `meshstep refine --split-segments interior|none` and its recipe line: the written mesh keeps
// the segments it should, the summary and the statistics say what was left over the bound,
// help and `meshstep list` name the option, and a bad word or bisection is a usage error.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "meshstep/io/triangle_io.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using testing::CommandResult;

// A 4 x 4 square with a 2 x 2 hole, and a wall (an interior segment) below the hole.
constexpr const char* kSquareWithHoleAndWall =
    "10 2 0 1\n"
    "1 0 0 1\n2 4 0 1\n3 4 4 1\n4 0 4 1\n5 1 1.5 2\n6 3 1.5 2\n7 3 3 2\n8 1 3 2\n9 0.5 0.5 3\n10 3.5 0.5 3\n"
    "9 1\n"
    "1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n9 9 10 3\n"
    "1\n1 2 2.2\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::set<std::pair<std::uint32_t, std::uint32_t>> segment_set(const std::vector<Segment>& segments) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const Segment& s : segments) out.insert({std::min(s.a, s.b), std::max(s.a, s.b)});
  return out;
}

class SegmentSplitsCli : public testing::CliTest {
 protected:
  SegmentSplitsCli() : CliTest("meshstep_segment_splits_cli_") {}
};

TEST_F(SegmentSplitsCli, NoneWritesTheInputsSegmentsAndSaysWhatIsLeft) {
  const std::string input = write("box.poly", kSquareWithHoleAndWall);
  const Pslg in = io::read_pslg(input);
  const CommandResult r =
      meshstep("refine " + input + " --min-angle 30 --split-segments none -o " + file("none") + " --stats json");
  ASSERT_EQ(r.status, 0) << r.err;
  const TriMesh m = io::read_mesh(file("none"));
  EXPECT_EQ(segment_set(m.segments), segment_set(in.segments));
  const std::string json = testing::stats_line(r.out);
  EXPECT_EQ(testing::json_field(json, "split_segments"), "\"none\"") << json;
  EXPECT_EQ(testing::json_field(json, "segment_splits"), "0") << json;
  EXPECT_NE(testing::json_field(json, "kept_segment_refusals"), "0") << json;
  EXPECT_EQ(testing::json_field(json, "bounds_met"), "false") << json;
  EXPECT_TRUE(contains(r.out, "bad triangles set aside by kept segments")) << r.out;
  EXPECT_TRUE(contains(r.out, "bounds missed by " + testing::json_field(json, "bad_triangles") + " triangles")) << r.out;

  // Without the option the same run splits segments, and meets the bound.
  const CommandResult all = meshstep("refine " + input + " --min-angle 30 -o " + file("all") + " --stats json");
  ASSERT_EQ(all.status, 0) << all.err;
  EXPECT_GT(io::read_mesh(file("all")).segments.size(), in.segments.size());
  EXPECT_EQ(testing::json_field(testing::stats_line(all.out), "bounds_met"), "true");
  EXPECT_FALSE(contains(all.out, "set aside")) << all.out;
}

TEST_F(SegmentSplitsCli, InteriorKeepsTheBoundaryAndARecipeLineSaysTheSame) {
  const std::string input = write("box.poly", kSquareWithHoleAndWall);
  const CommandResult r = meshstep("refine " + input + " --min-angle 30 --split-segments interior -q -o " + file("y"));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto segments = segment_set(io::read_mesh(file("y")).segments);
  // The square's and the hole's segments (0-based ends) are whole; the wall (8-9) is not.
  for (const auto& [a, b] : {std::pair{0u, 1u}, {1u, 2u}, {2u, 3u}, {0u, 3u}, {4u, 5u}, {5u, 6u}, {6u, 7u}, {4u, 7u}})
    EXPECT_TRUE(segments.contains({a, b})) << a << "-" << b;
  EXPECT_FALSE(segments.contains({8u, 9u}));

  const std::string recipe = write("y.recipe", "refine --min-angle 30 --split-segments interior\n");
  ASSERT_EQ(meshstep("run " + recipe + " " + input + " -q -o " + file("run")).status, 0);
  for (const char* ext : {".node", ".ele", ".poly"})
    EXPECT_EQ(testing::slurp(file("run") + ext), testing::slurp(file("y") + ext)) << ext;
}

TEST_F(SegmentSplitsCli, HelpAndListNameItAndBadUseIsAUsageError) {
  const CommandResult help = meshstep("refine --help");
  EXPECT_TRUE(contains(help.out, "--split-segments")) << help.out;
  EXPECT_TRUE(contains(help.out, "{all,interior,none}")) << help.out;
  const CommandResult list = meshstep("list");
  EXPECT_TRUE(contains(list.out, "--split-segments")) << list.out;
  EXPECT_TRUE(contains(list.out, "Triangle's -YY")) << list.out;

  const std::string input = write("box.poly", kSquareWithHoleAndWall);
  const CommandResult bad = meshstep("refine " + input + " --split-segments boundary -o " + file("bad"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(contains(bad.err, "--split-segments")) << bad.err;
  const CommandResult bisection =
      meshstep("refine " + input + " -a lepp-bisection --max-area 0.1 --split-segments none -o " + file("bis"));
  EXPECT_EQ(bisection.status, 2);
  EXPECT_TRUE(contains(bisection.err, "bisection")) << bisection.err;
  EXPECT_FALSE(std::filesystem::exists(file("bad.node")));
  EXPECT_FALSE(std::filesystem::exists(file("bis.node")));
}

}  // namespace
}  // namespace meshstep
