// One numbering everywhere (issue 29): step K is the same moment in render, export, log
// mesh, log check, log dump and explain, and every command refuses K = n + 1 in the same
// words; a vertex is named by its number in the output's .node in every text, and a vertex
// the run removes again by a name no survivor has.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/io/triangle_io.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/image.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_meshstep;
using testing::slurp;
using testing::TempDir;

std::string lesson() { return std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly"; }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class OneNumbering : public testing::CliTest {
 protected:
  void SetUp() override {
    log_ = dir_.file("lesson.mslog");
    const CommandResult r = meshstep("refine " + lesson() + " --algorithm offcenter --min-angle 30 --record " + log_ +
                                     " -o " + dir_.file("lesson") + " -q");
    ASSERT_EQ(r.status, 0) << r.err;
    n_ = replay::LogReader(log_).step_count();
    ASSERT_GT(n_, 10u);
  }
  std::string k(std::uint64_t v) const { return std::to_string(v); }

  std::string log_;
  std::uint64_t n_ = 0;
};

// Every command accepts the last moment n and refuses n + 1, in the same words.
TEST_F(OneNumbering, EveryCommandAcceptsStepNAndRefusesNPlusOneInTheSameWords) {
  const std::string n = k(n_), beyond = k(n_ + 1);
  const std::string words = "is outside the run: its steps are numbered 0.." + n;
  struct Case {
    std::string ok, refused;
  };
  const std::vector<Case> cases = {
      {"render " + log_ + " --step " + n + " -o " + dir_.file("a.svg") + " -q",
       "render " + log_ + " --step " + beyond + " -o " + dir_.file("b.svg") + " -q"},
      {"log mesh " + log_ + " --step " + n + " -o " + dir_.file("m"),
       "log mesh " + log_ + " --step " + beyond + " -o " + dir_.file("m2")},
      {"log check " + log_ + " --from " + k(n_ - 1) + " --to " + n, "log check " + log_ + " --to " + beyond},
      {"explain " + log_ + " --step " + n, "explain " + log_ + " --step " + beyond},
  };
  for (const Case& c : cases) {
    const CommandResult ok = meshstep(c.ok);
    EXPECT_EQ(ok.status, 0) << c.ok << "\n" << ok.err;
    const CommandResult refused = meshstep(c.refused);
    EXPECT_EQ(refused.status, 2) << c.refused;
    EXPECT_TRUE(contains(refused.err, words)) << c.refused << "\n" << refused.err;
    EXPECT_TRUE(refused.out.empty()) << c.refused << "\n" << refused.out;
  }
  // export checks its range before it draws anything, so no OpenGL is needed to be refused.
  const CommandResult export_refused =
      meshstep("export " + log_ + " --frames " + dir_.file("f") + " --from 0 --to " + beyond + " -q");
  EXPECT_EQ(export_refused.status, 2);
  EXPECT_TRUE(contains(export_refused.err, words)) << export_refused.err;
  EXPECT_FALSE(fs::exists(dir_.file("f")));
  // The mesh written for step n is the run's own output.
  EXPECT_EQ(slurp(dir_.file("m.ele")), slurp(dir_.file("lesson.ele")));
}

// Step K names one moment: render's report, explain's heading, the caption in the SVG, and
// the mesh log mesh writes all say the same K.
TEST_F(OneNumbering, StepKIsOneMomentInRenderExplainAndLogMesh) {
  for (const std::uint64_t step : {std::uint64_t{1}, std::uint64_t{7}, n_}) {
    const std::string svg = dir_.file("s" + k(step) + ".svg");
    const CommandResult render = meshstep("render " + log_ + " --step " + k(step) + " -o " + svg);
    ASSERT_EQ(render.status, 0) << render.err;
    EXPECT_TRUE(contains(render.out, "at step " + k(step) + " of " + k(n_))) << render.out;
    EXPECT_TRUE(contains(slurp(svg), "step " + k(step) + " of " + k(n_))) << "the caption at step " << step;
    const CommandResult explain = meshstep("explain " + log_ + " --step " + k(step));
    ASSERT_EQ(explain.status, 0) << explain.err;
    EXPECT_EQ(explain.out.rfind("step " + k(step) + " of " + k(n_), 0), 0u) << explain.out;
    const CommandResult mesh = meshstep("log mesh " + log_ + " --step " + k(step) + " -o " + dir_.file("m"));
    ASSERT_EQ(mesh.status, 0) << mesh.err;
    EXPECT_TRUE(contains(mesh.out, "mesh after " + k(step) + " of " + k(n_) + " steps")) << mesh.out;
  }
  const CommandResult start = meshstep("explain " + log_ + " --step 0 --json");
  ASSERT_EQ(start.status, 0) << start.err;
  EXPECT_TRUE(contains(start.out, "\"step\":0,")) << start.out;
  EXPECT_TRUE(contains(start.out, "\"heading\":\"start\"")) << start.out;
}

// log dump puts step K's events under "step K": they take the mesh from the moment K - 1
// (render --step K-1) to the moment K.
TEST_F(OneNumbering, LogDumpNamesEachEventByTheStepThatEndsAtItsMoment) {
  const replay::LogReader log(log_);
  for (const std::uint64_t step : {std::uint64_t{1}, std::uint64_t{2}, n_}) {
    // Step K's events run from the moment K - 1 to the moment K.
    const std::uint64_t first = replay::step_position(log, step - 1), last = replay::step_position(log, step) - 1;
    const CommandResult dump = meshstep("log dump " + log_ + " --from " + k(first) + " --to " + k(last));
    ASSERT_EQ(dump.status, 0) << dump.err;
    for (const std::string& line : lines_of(dump.out))
      EXPECT_TRUE(contains(line, " [step " + k(step) + "] ")) << line;
    const CommandResult json = meshstep("log dump " + log_ + " --jsonl --from " + k(first) + " --to " + k(first));
    EXPECT_TRUE(contains(json.out, "\"step\":" + k(step) + ",")) << json.out;
  }
  const CommandResult preamble = meshstep("log dump " + log_ + " --to 0");
  EXPECT_TRUE(contains(preamble.out, "[preamble]")) << preamble.out;
}

// The frames export draws for steps A..B are the pictures render draws for --step A..B
// (with one --view: export holds one camera for the whole run, render fits its moment).
TEST_F(OneNumbering, ExportDrawsTheMomentsRenderDraws) {
  const CommandResult probe = meshstep("render " + log_ + " --step 0 -o " + dir_.file("probe.png") + " -q");
  if (probe.status != 0) GTEST_SKIP() << "no OpenGL here: " << probe.err;
  const CommandResult frames = meshstep("export " + log_ + " --frames " + dir_.file("f") + " --from " + k(n_ - 1) +
                                        " --to " + k(n_) + " --size 160x100 --view -1,-1,12,8 -q");
  ASSERT_EQ(frames.status, 0) << frames.err;
  // Each frame is its step's picture, and not the other step's (export's scenes may differ
  // from render's by a few antialiased pixels: what counts is which moment is drawn).
  for (const std::uint64_t step : {n_ - 1, n_})
    ASSERT_EQ(meshstep("render " + log_ + " --step " + k(step) + " --size 160x100 --view -1,-1,12,8 -o " +
                       dir_.file("r" + k(step) + ".png") + " -q")
                  .status,
              0);
  const scene::Image r0 = scene::read_png(dir_.file("r" + k(n_ - 1) + ".png"));
  const scene::Image r1 = scene::read_png(dir_.file("r" + k(n_) + ".png"));
  const scene::Image f0 = scene::read_png(dir_.file("f/frame_000000.png"));
  const scene::Image f1 = scene::read_png(dir_.file("f/frame_000001.png"));
  const std::size_t apart = scene::compare_images(r0, r1, 8).differing_pixels;
  EXPECT_GT(apart, 20u) << "two moments that look alike prove nothing";
  EXPECT_LT(scene::compare_images(f0, r0, 8).differing_pixels, apart / 4) << "frame 0 is step " << n_ - 1;
  EXPECT_LT(scene::compare_images(f1, r1, 8).differing_pixels, apart / 4) << "frame 1 is step " << n_;
  // The viewer's default range: every step from 0 to n.
  const CommandResult all = meshstep("export " + log_ + " --frames " + dir_.file("all") + " --from 0 --to " + k(n_) +
                                     " --size 80x60 -q");
  ASSERT_EQ(all.status, 0) << all.err;
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_.file("all"))) ++count;
  EXPECT_EQ(count, n_ + 1);
}

// Vertices: in every text a vertex is its number in the output's .node.
TEST_F(OneNumbering, VertexNamesAreTheOutputNodeNumbers) {
  const replay::LogReader log(log_);
  const TriMesh output = io::read_mesh(dir_.file("lesson"));
  ASSERT_EQ(output.first_index, 1) << "lesson.poly is 1-based";
  std::set<std::string> names;
  std::size_t inputs = 0;
  for (VertexId v = 0; v < log.vertices().size(); ++v) {
    const replay::VertexInfo& info = log.vertices()[v];
    if (info.event == kNone) continue;
    const std::string name = log.vertex_name(v);
    ASSERT_TRUE(names.insert(name).second) << "two vertices named " << name;
    if (info.removed != UINT64_MAX) {  // no number in the output (this run deletes encroaching vertices)
      EXPECT_EQ(name.front(), 'r') << "vertex " << v;
      EXPECT_EQ(log.output_number(v), kNone);
      continue;
    }
    ASSERT_TRUE(!name.empty() && name.find_first_not_of("0123456789") == std::string::npos)
        << "vertex " << v << " is named " << name;
    const long number = std::stol(name);
    ASSERT_GE(number, 1);
    ASSERT_LT(static_cast<std::size_t>(number - 1), output.points.size());
    EXPECT_EQ(output.points[number - 1], info.point) << "vertex " << name << " (log id " << v << ")";
    if (info.input_index < log.run().input_vertices) {
      EXPECT_EQ(number, static_cast<long>(info.input_index) + 1) << "input vertices keep their input numbers";
      ++inputs;
    }
  }
  EXPECT_EQ(inputs, log.run().input_vertices);
  // The explanation of a refinement step names the vertex it inserted by that number.
  replay::Replay cursor(log);
  for (std::uint64_t step = 1; step <= log.step_count(); ++step) {
    if (log.step_kind(step - 1) != replay::StepKind::refine) continue;
    VertexId inserted = kNone;
    for (std::uint64_t e = log.step_start(step - 1); e < log.step_start(step); ++e)
      if (log.event(e).type == replay::EventType::vertex) inserted = log.event(e).ids[0];
    ASSERT_NE(inserted, kNone);
    const std::string number = log.vertex_name(inserted);
    ASSERT_NE(number, std::to_string(inserted)) << "pick a step where the log id and the number differ";
    const CommandResult explain = meshstep("explain " + log_ + " --step " + k(step));
    EXPECT_TRUE(contains(explain.out, "vertex " + number)) << explain.out;
    const CommandResult dump = meshstep("log dump " + log_ + " --from " + k(log.step_start(step - 1)) + " --to " +
                                        k(log.step_start(step) - 1));
    EXPECT_TRUE(contains(dump.out, " vertex vertex=" + number + " input=steiner ")) << dump.out;
    const CommandResult raw = meshstep("log dump --log-ids " + log_ + " --from " + k(log.step_start(step - 1)) +
                                       " --to " + k(log.step_start(step) - 1));
    EXPECT_TRUE(contains(raw.out, " vertex vertex=" + std::to_string(inserted) + " ")) << raw.out;
    break;
  }
}

// A vertex the run removes again has no number in the output: it is named rK everywhere.
TEST_F(OneNumbering, RemovedVerticesHaveNamesNoSurvivorHas) {
  const std::string log_path = dir_.file("improve.mslog");
  ASSERT_EQ(meshstep("refine " + lesson() + " --algorithm improve --min-angle 30 --max-area 1 --record " + log_path +
                     " -o " + dir_.file("improved") + " -q")
                .status,
            0);
  const replay::LogReader log(log_path);
  std::uint64_t removal_step = 0;
  VertexId removed = kNone;
  for (std::uint64_t s = 0; s < log.step_count() && removed == kNone; ++s)
    if (log.step_kind(s) == replay::StepKind::remove_vertex) {
      removal_step = s + 1;
      removed = log.event(log.step_start(s)).ids[0];
    }
  if (removed == kNone) GTEST_SKIP() << "this run removed no vertex";
  const std::string name = log.vertex_name(removed);
  ASSERT_EQ(name.front(), 'r') << name;
  EXPECT_EQ(log.output_number(removed), kNone);
  const CommandResult explain = meshstep("explain " + log_path + " --step " + k(removal_step));
  ASSERT_EQ(explain.status, 0) << explain.err;
  EXPECT_TRUE(contains(explain.out, "vertex " + name + " removed")) << explain.out;
  // The survivors are numbered 1..N without a gap, as the output's .node numbers them.
  const TriMesh output = io::read_mesh(dir_.file("improved"));
  std::set<std::uint32_t> numbers;
  for (VertexId v = 0; v < log.vertices().size(); ++v)
    if (log.vertices()[v].event != kNone && log.output_number(v) != kNone) numbers.insert(log.output_number(v));
  ASSERT_EQ(numbers.size(), output.points.size());
  EXPECT_EQ(*numbers.begin(), 1u);
  EXPECT_EQ(*numbers.rbegin(), output.points.size());
}

}  // namespace
}  // namespace meshstep
