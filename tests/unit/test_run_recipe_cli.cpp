// `meshstep run RECIPE INPUT`: a chain of operations on one mesh (the second's area bound
// holds in its box and not elsewhere), a one-line recipe writes byte for byte what
// `meshstep refine` writes, and every bad line is refused as RECIPE:LINE before any work.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/region.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/operations.hpp"
#include "meshstep/scene/pseudocode.hpp"
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

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

double area_of(const TriMesh& m, const std::array<std::uint32_t, 3>& t) {
  const Point &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

class RunRecipeCli : public testing::CliTest {
 protected:
  RunRecipeCli() : CliTest("meshstep_run_recipe_cli_") {}
};

// Lepp-centroid to 25 degrees everywhere, then an area bound in a box: the area bound holds
// where a triangle's centroid is in the box, and not elsewhere.
TEST_F(RunRecipeCli, AChainsSecondBoundHoldsInItsRegionOnly) {
  const std::string input = write("square.poly", kSquare);
  const std::string recipe = write("chain.recipe",
                                   "# quality first, then small triangles in a box\n"
                                   "refine --algorithm lepp-centroid --min-angle 25 --max-area 2\n"
                                   "\n"
                                   "refine --algorithm midpoint-area --max-area 0.05 --region 1,1,4,4  # the box\n");
  const CommandResult r = meshstep("run " + recipe + " " + input + " -o " + dir_.file("chain") + " --stats json");
  ASSERT_EQ(r.status, 0) << r.err;
  const TriMesh m = io::read_mesh(dir_.file("chain"));
  const RefineRegion box = RefineRegion::box({1, 1}, {4, 4});
  std::size_t inside = 0, large_inside = 0, large_outside = 0;
  for (const auto& t : m.triangles) {
    const Point &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    const bool large = area_of(m, t) > 0.05 * (1 + 1e-12);
    if (box.contains({(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0})) {
      ++inside;
      large_inside += large;
    } else {
      large_outside += large;
    }
  }
  EXPECT_GT(inside, 100u);
  EXPECT_EQ(large_inside, 0u);
  EXPECT_GT(large_outside, 5u);
  EXPECT_EQ(meshstep("check " + dir_.file("chain") + " --poly " + input + " -q").status, 0);

  // The first operation alone leaves large triangles in the box: the second did the work.
  const std::string first = write("first.recipe", "refine --algorithm lepp-centroid --min-angle 25 --max-area 2\n");
  ASSERT_EQ(meshstep("run " + first + " " + input + " -q -o " + dir_.file("first")).status, 0);
  EXPECT_LT(io::read_mesh(dir_.file("first")).triangles.size() + 100, m.triangles.size());
}

// The region of a recipe's line written out (--region-polygon): the recipe is one file, and
// the bound holds in the triangle it names and not elsewhere.
TEST_F(RunRecipeCli, ARecipeLinesInlinePolygonLimitsItsOperation) {
  const std::string input = write("square.poly", kSquare);
  const std::string recipe = write("lasso.recipe",
                                   "refine --algorithm lepp-centroid --min-angle 25 --max-area 2\n"
                                   "refine --max-area 0.05 --region-polygon 1,1,7,1,1,7\n");
  const CommandResult r = meshstep("run " + recipe + " " + input + " -o " + dir_.file("lasso") + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const TriMesh m = io::read_mesh(dir_.file("lasso"));
  const RefineRegion triangle = RefineRegion::polygon({{1, 1}, {7, 1}, {1, 7}});
  std::size_t inside = 0, large_inside = 0, large_outside = 0;
  for (const auto& t : m.triangles) {
    const Point &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    const bool large = area_of(m, t) > 0.05 * (1 + 1e-12);
    if (triangle.contains({(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0})) {
      ++inside;
      large_inside += large;
    } else {
      large_outside += large;
    }
  }
  EXPECT_GT(inside, 100u);
  EXPECT_EQ(large_inside, 0u);
  EXPECT_GT(large_outside, 5u);
  EXPECT_EQ(meshstep("check " + dir_.file("lasso") + " --poly " + input + " -q").status, 0);
}

// A 5-degree wedge, whose tip no refinement can fix: every operation leaves triangles there.
constexpr const char* kWedge =
    "# a 5-degree wedge\n"
    "3 2 0 0\n1 0 0\n2 10 0\n3 9.961946980917455 0.8715574274765817\n"
    "3 0\n1 1 2\n2 2 3\n3 3 1\n"
    "0\n";

// The run's --stats json counts what every operation did: the triangles left alone at a small
// input angle too (the command line once reported only the first operation's).
TEST_F(RunRecipeCli, TheStatsAddUpTheSkippedTrianglesOfEveryOperation) {
  const std::string input = write("wedge.poly", kWedge);
  const auto skipped = [&](const std::string& recipe_text) {
    const std::string recipe = write("r.recipe", recipe_text);
    const CommandResult r = meshstep("run " + recipe + " " + input + " -o " + dir_.file("out") + " --stats json -q");
    EXPECT_EQ(r.status, 0) << r.err;
    return std::stoul(testing::json_field(testing::stats_line(r.out), "skipped_small_angle"));
  };
  const unsigned long first = skipped("refine --min-angle 20\n");
  const unsigned long both = skipped("refine --min-angle 20\nrefine --min-angle 28 --max-area 0.5\n");
  EXPECT_GT(first, 0u);
  EXPECT_GT(both, first);
}

// `meshstep refine` is a recipe of one operation: the same files, byte for byte, the log too.
// `run` takes refine's output options, registered once for both (planar_output_options.hpp):
// --no-output runs the recipe and writes no mesh, with the same statistics.
TEST_F(RunRecipeCli, TakesRefinesOutputOptions) {
  const std::string input = write("square.poly", kSquare);
  const std::string recipe = write("two.recipe", "refine --min-angle 25\nrefine --max-area 0.5 --region 2,2,6,7\n");
  const CommandResult written = meshstep("run " + recipe + " " + input + " -q --stats json -o " + file("w"));
  ASSERT_EQ(written.status, 0) << written.err;
  ASSERT_TRUE(std::filesystem::exists(file("w.node")));
  const CommandResult none = meshstep("run " + recipe + " " + input + " -q --stats json --no-output -o " + file("n"));
  ASSERT_EQ(none.status, 0) << none.err;
  EXPECT_FALSE(std::filesystem::exists(file("n.node")));
  EXPECT_FALSE(std::filesystem::exists(file("n.ele")));
  for (const char* key : {"steiner", "triangles", "min_angle"})
    EXPECT_EQ(testing::json_field(testing::stats_line(none.out), key), testing::json_field(testing::stats_line(written.out), key))
        << key;
}

TEST_F(RunRecipeCli, AOneLineRecipeWritesWhatRefineWrites) {
  const std::string input = write("square.poly", kSquare);
  const std::vector<std::string> lines = {
      "refine --algorithm lepp-centroid --min-angle 25",
      "refine --algorithm offcenter --min-angle 30 --max-area 0.5 --region 2,2,6,7",
      "refine --algorithm lepp-bisection --max-area 0.3",
      "refine --algorithm improve --min-angle 28 --ds dcel --insertion cavity",
  };
  int n = 0;
  for (const std::string& line : lines) {
    SCOPED_TRACE(line);
    const std::string a = dir_.file("a" + std::to_string(n)), b = dir_.file("b" + std::to_string(n));
    const std::string recipe = write("one" + std::to_string(n++) + ".recipe", line + "\n");
    const CommandResult ra = meshstep(line + " " + input + " -q -o " + a + " --record " + a + ".mslog");
    const CommandResult rb = meshstep("run " + recipe + " " + input + " -q -o " + b + " --record " + b + ".mslog");
    ASSERT_EQ(ra.status, 0) << ra.err;
    ASSERT_EQ(rb.status, 0) << rb.err;
    for (const char* ext : {".node", ".ele", ".poly", ".mslog"}) {
      const std::string fa = testing::slurp(a + ext), fb = testing::slurp(b + ext);
      EXPECT_FALSE(fa.empty()) << ext;
      EXPECT_TRUE(fa == fb) << ext << " differs";
    }
  }
}

// The numbers after each `"to_step":` in `log info --json`'s operations, in order.
std::vector<std::string> to_steps(const std::string& json) {
  std::vector<std::string> steps;
  const std::string key = "\"to_step\":";
  for (std::size_t at = json.find(key); at != std::string::npos; at = json.find(key, at + 1)) {
    const std::size_t from = at + key.size();
    steps.push_back(json.substr(from, json.find_first_not_of("0123456789", from) - from));
  }
  return steps;
}

// One log for the whole recipe: `log info` lists its operations with their steps, and the
// log's mesh at the end of each operation is, file for file, what the recipe cut after that
// operation writes. The third operation runs in two phases (aspect, then angle) and the
// second improves, so the phases of each must be counted right.
TEST_F(RunRecipeCli, ARecipeIsRecordedInOneLogAndEachOperationEndsWhereItsRecipeWould) {
  const std::string input = write("square.poly", kSquare);
  const std::vector<std::string> lines = {
      "refine --algorithm lepp-centroid --min-angle 25 --max-area 2",
      "refine --algorithm offcenter --min-angle 28 --max-area 0.1 --improve --region 1,1,4,4",
      "refine --algorithm combined --min-angle 30 --max-area 0.4",
  };
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  const std::string recipe = write("chain.recipe", text);
  const std::string log = dir_.file("chain.mslog");
  const CommandResult r = meshstep("run " + recipe + " " + input + " -q -o " + dir_.file("chain") + " --record " + log);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(meshstep("log verify " + log).status, 0);

  const CommandResult info = meshstep("log info " + log + " --json");
  ASSERT_EQ(info.status, 0) << info.err;
  const std::vector<std::string> ends = to_steps(info.out);
  ASSERT_EQ(ends.size(), lines.size()) << info.out;
  EXPECT_EQ(std::count(info.out.begin(), info.out.end(), '['), 1) << info.out;
  const CommandResult listed = meshstep("log info " + log);
  EXPECT_TRUE(contains(listed.out, "operations: 3")) << listed.out;
  EXPECT_TRUE(contains(listed.out, "2. refine --min-angle 28 --max-area 0.1 --improve")) << listed.out;

  std::string cut;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    SCOPED_TRACE(lines[i]);
    cut += lines[i] + "\n";
    const std::string part = write("part" + std::to_string(i) + ".recipe", cut);
    const std::string alone = dir_.file("alone" + std::to_string(i)), at = dir_.file("at" + std::to_string(i));
    ASSERT_EQ(meshstep("run " + part + " " + input + " -q -o " + alone).status, 0);
    const CommandResult m = meshstep("log mesh " + log + " --step " + ends[i] + " -o " + at);
    ASSERT_EQ(m.status, 0) << m.err;
    for (const char* ext : {".node", ".ele"}) {
      const std::string fa = testing::slurp(alone + ext), fb = testing::slurp(at + ext);
      EXPECT_FALSE(fa.empty()) << ext;
      EXPECT_TRUE(fa == fb) << ext << " differs at the end of operation " << i + 1;
    }
  }
  // The operations end one after the other, the last where the log does.
  EXPECT_LT(std::stoull(ends[0]), std::stoull(ends[1]));
  EXPECT_LT(std::stoull(ends[1]), std::stoull(ends[2]));
}

// In a recipe's log the pseudo-code panel follows the operation at the cursor: Lepp-centroid
// in the first, off-centers in the second, and vertex removal in the second's improvement.
TEST_F(RunRecipeCli, ThePseudoCodeFollowsTheOperationAtTheCursor) {
  const std::string input = write("square.poly", kSquare);
  const std::string recipe = write("two.recipe",
                                   "refine --algorithm lepp-centroid --min-angle 25 --max-area 2\n"
                                   "refine --algorithm offcenter --min-angle 28 --max-area 0.1 --improve\n");
  const std::string log_path = dir_.file("two.mslog");
  ASSERT_EQ(meshstep("run " + recipe + " " + input + " -q -o " + dir_.file("two") + " --record " + log_path).status, 0);
  const replay::LogReader log(log_path);
  EXPECT_EQ(log.format_version(), 6u);  // the first whose header names operations
  const std::vector<replay::OperationSpan> spans = replay::operation_spans(log, log_path);
  ASSERT_EQ(spans.size(), 2u);
  ASSERT_LT(spans[0].from_step, spans[0].to_step);
  ASSERT_LT(spans[1].from_step, spans[1].to_step);
  std::vector<std::string> seen;  // each phase's program, by its title
  for (const replay::PhaseSpan& p : log.phases()) {
    if (p.phase != replay::Phase::refine && p.phase != replay::Phase::improve) continue;
    if (p.end == p.begin + 2) continue;  // an empty phase: its begin and end alone
    seen.push_back(scene::pseudocode_at(log, p.begin + 2).code->title);
  }
  const std::vector<std::string> expected = {scene::pseudocode(Selection::lepp_centroid).title,
                                             scene::pseudocode(Selection::offcenter).title,
                                             scene::pseudocode(scene::Program::vertex_removal).title};
  EXPECT_EQ(seen, expected);
}

// Each bad line: RECIPE:LINE: what is wrong, exit status 1, nothing written.
TEST_F(RunRecipeCli, BadLinesAreRefusedBeforeAnyWork) {
  const std::string input = write("square.poly", kSquare);
  const std::string bowtie = write("bowtie.poly",
                                   "4 2 0 0\n1 0 0\n2 2 2\n3 2 0\n4 0 2\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n");
  const std::string good = "refine --algorithm lepp-centroid --min-angle 25\n# a comment\n\n";
  const auto refused = [&](const std::string& bad_line, const std::string& message) {
    SCOPED_TRACE(bad_line);
    const std::string recipe = write("bad.recipe", good + bad_line + "\n");
    const std::string out = dir_.file("out");
    const CommandResult r = meshstep("run " + recipe + " " + input + " -o " + out + " --record " + out + ".mslog");
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(contains(r.err, "error: " + recipe + ":4: ")) << r.err;
    EXPECT_TRUE(contains(r.err, message)) << r.err;
    EXPECT_FALSE(contains(r.err, "internal error")) << r.err;
    for (const char* ext : {".node", ".ele", ".poly", ".mslog", ".mslog.partial"})
      EXPECT_FALSE(std::filesystem::exists(out + ext)) << ext;
    EXPECT_FALSE(contains(r.err, "reading")) << "work began: " << r.err;
  };
  refused("refine --algorithm nope", "--algorithm: 'nope' is not one of");
  refused("refine --min-angle -3", "--min-angle: must be zero or a positive number, not -3");
  refused("refine --max-area 0", "--max-area: must be a positive number, not 0");
  refused("refine --min-angle 25 --colour red", "unknown option --colour");
  refused("refine --min-angle 25 --region 1,2,3", "--region: a region box is X0,Y0,X1,Y1");
  refused("refine --min-angle 25 --region 3,1,1,3", "--region: the region box 3,1,1,3 is empty");
  refused("refine --min-angle 25 --region-poly " + bowtie, "--region-poly: " + bowtie + ": a region polygon's");
  refused("refine --min-angle 25 --region 1,1,2,2 --region-poly " + bowtie, "give one");
  refused("refine --min-angle 25 --region-polygon 0,0,2,2,2,0,0,2",
          "--region-polygon: a region polygon's edge 1 (0,0 to 2,2) and edge 3 (2,0 to 0,2) touch or cross");
  refused("triangulate --convex-hull", "'refine ...' expected");
  refused("smooth --min-angle 25", "unknown operation 'smooth'");
  refused("refine --algorithm improve --insertion bisection", "does not go with bisection");
  refused("refine --algorithm midpoint-area", "midpoint-area needs a bound");
}

}  // namespace
}  // namespace meshstep
