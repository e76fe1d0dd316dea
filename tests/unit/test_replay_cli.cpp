// `meshstep triangulate --record` and `meshstep log info|dump|mesh|verify`: the replay
// log's command-line contract (outputs, exit statuses, error format).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <cctype>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/io/triangle_io.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;

using testing::CommandResult;
using testing::slurp;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The number right after the first `before` in `text` (digits only), or -1.
long long number_after(const std::string& text, const std::string& before) {
  const std::size_t at = text.find(before);
  if (at == std::string::npos) return -1;
  std::size_t end = at + before.size();
  long long value = -1;
  for (; end < text.size() && std::isdigit(static_cast<unsigned char>(text[end])); ++end)
    value = (value < 0 ? 0 : value * 10) + (text[end] - '0');
  return value;
}

class ReplayCli : public testing::CliTest {
 protected:
  ReplayCli() : CliTest("meshstep_replay_cli_") {}

  // Records the example plate into LOG with its mesh written to PREFIX.*.
  void record_plate() {
    const CommandResult r = meshstep("triangulate " + plate_ + " --record " + log_ + " -o " + prefix_);
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_TRUE(fs::exists(log_));
    ASSERT_FALSE(fs::exists(log_ + ".partial"));
    ASSERT_TRUE(fs::exists(prefix_ + ".ele"));
  }

  const std::string plate_ = std::string(MESHSTEP_ASSETS) + "/examples/plate.poly";
  const std::string log_ = dir_.file("plate.mslog");
  const std::string prefix_ = dir_.file("plate");
};

TEST_F(ReplayCli, InfoDescribesTheRun) {
  record_plate();
  const CommandResult text = meshstep("log info " + log_);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_TRUE(contains(text.out, "meshstep replay log")) << text.out;
  EXPECT_TRUE(contains(text.out, "plate.poly")) << text.out;
  EXPECT_TRUE(contains(text.out, "complete:   yes")) << text.out;
  EXPECT_TRUE(text.err.empty()) << text.err;

  const CommandResult json = meshstep("log info " + log_ + " --json");
  ASSERT_EQ(json.status, 0) << json.err;
  const std::vector<std::string> out = lines(json.out);
  ASSERT_FALSE(out.empty());
  const std::string& last = out.back();
  ASSERT_FALSE(last.empty());
  EXPECT_EQ(last.front(), '{');
  EXPECT_EQ(last.back(), '}');
  for (const char* key : {"\"events\":", "\"complete\":true", "\"steps\":", "\"data_structure\":\"tds\"",
                          "\"insertion\":\"flip\"", "\"algorithm\":\"triangulate\""})
    EXPECT_TRUE(contains(last, key)) << key << " in " << last;
  // There is always a keyframe: the final one, at the end of the run.
  EXPECT_GE(number_after(last, "\"keyframes\":"), 1) << last;
}

TEST_F(ReplayCli, DumpPrintsOneLinePerEvent) {
  record_plate();
  const CommandResult text = meshstep("log dump " + log_ + " --from 0 --to 20");
  ASSERT_EQ(text.status, 0) << text.err;
  const std::vector<std::string> out = lines(text.out);
  ASSERT_EQ(out.size(), 21u) << text.out;
  for (std::size_t i = 0; i < out.size(); ++i)
    EXPECT_EQ(out[i].rfind(std::to_string(i) + " [", 0), 0u) << out[i];  // numbered from --from
  EXPECT_TRUE(contains(out[0], "preamble")) << out[0];                   // phase_begin comes first

  const CommandResult jsonl = meshstep("log dump " + log_ + " --jsonl --to 5");
  ASSERT_EQ(jsonl.status, 0) << jsonl.err;
  const std::vector<std::string> objects = lines(jsonl.out);
  ASSERT_EQ(objects.size(), 6u) << jsonl.out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    EXPECT_EQ(objects[i].rfind("{\"event\":" + std::to_string(i) + ",", 0), 0u) << objects[i];
    EXPECT_EQ(objects[i].back(), '}') << objects[i];
  }
}

TEST_F(ReplayCli, MeshAtTheEndIsTheTriangulatedMesh) {
  record_plate();
  const std::string p2 = dir_.file("replayed");
  const CommandResult end = meshstep("log mesh " + log_ + " --step -1 -o " + p2);
  ASSERT_EQ(end.status, 0) << end.err;
  ASSERT_TRUE(fs::exists(p2 + ".ele"));
  EXPECT_EQ(slurp(p2 + ".ele"), slurp(prefix_ + ".ele"));  // byte for byte
  EXPECT_EQ(io::read_mesh(p2).points.size(), io::read_mesh(prefix_).points.size());

  const std::string p3 = dir_.file("early");
  const CommandResult early = meshstep("log mesh " + log_ + " --step 5 -o " + p3);
  ASSERT_EQ(early.status, 0) << early.err;
  EXPECT_LT(io::read_mesh(p3).triangles.size(), io::read_mesh(prefix_).triangles.size());

  const CommandResult beyond = meshstep("log mesh " + log_ + " --step 99999 -o " + dir_.file("beyond"));
  EXPECT_EQ(beyond.status, 2);
  EXPECT_TRUE(contains(beyond.err, "meshstep: error:")) << beyond.err;
  EXPECT_TRUE(contains(beyond.err, "outside the run")) << beyond.err;
  EXPECT_FALSE(fs::exists(dir_.file("beyond.ele")));
}

TEST_F(ReplayCli, VerifyAcceptsTheLogAndRejectsDamage) {
  record_plate();
  const CommandResult ok = meshstep("log verify " + log_);
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_TRUE(contains(ok.out, ": ok:")) << ok.out;
  // Hashes are checked at keyframes only: each forward, backward and forward again, but the
  // final one is not revisited going back.
  const replay::LogReader log(log_);
  const long long keyframes = static_cast<long long>(log.keyframes().size());
  EXPECT_EQ(number_after(ok.out, "matched the algorithm's own at "), 3 * keyframes - 1) << ok.out;

  // One byte flipped in the middle of the file (inside a block's compressed payload).
  std::string bytes = slurp(log_);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x10);
  const std::string damaged = dir_.write("damaged.mslog", bytes);
  const CommandResult bad = meshstep("log verify " + damaged);
  EXPECT_EQ(bad.status, 1);
  EXPECT_EQ(bad.err.rfind("meshstep: error:", 0), 0u) << bad.err;
  EXPECT_TRUE(contains(bad.err, damaged)) << bad.err;

  // Cut short: opens as a prefix, but does not verify.
  const std::string cut = dir_.write("cut.mslog", slurp(log_).substr(0, bytes.size() - 10));
  const CommandResult truncated = meshstep("log verify " + cut);
  EXPECT_EQ(truncated.status, 1);
  EXPECT_TRUE(contains(truncated.err, "meshstep: error:")) << truncated.err;
  EXPECT_TRUE(contains(truncated.err, cut)) << truncated.err;

  const std::string missing = dir_.file("missing.mslog");
  const CommandResult none = meshstep("log verify " + missing);
  EXPECT_EQ(none.status, 1);
  EXPECT_TRUE(contains(none.err, "meshstep: error:")) << none.err;
  EXPECT_TRUE(contains(none.err, missing)) << none.err;
  EXPECT_EQ(meshstep("log info " + missing).status, 1);
}

// The final keyframe (the algorithm's own final mesh) altered on disk, nothing else
// changed: `log verify` and `log mesh` refuse the log.
TEST_F(ReplayCli, AlteredFinalKeyframeIsRejected) {
  record_plate();
  std::uint64_t payload = 0, end = 0;
  {
    const replay::LogReader log(log_);
    ASSERT_FALSE(log.keyframes().empty());
    const replay::KeyframeInfo& k = log.keyframes().back();
    ASSERT_EQ(k.event, log.event_count());
    payload = k.offset + 56;
    end = payload + k.stored_size;
  }
  std::string bytes = slurp(log_);
  ASSERT_LE(end, bytes.size());
  for (const std::uint64_t at : {payload, (payload + end) / 2, end - 1}) {
    SCOPED_TRACE("byte " + std::to_string(at) + " of the final keyframe's payload flipped");
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x04);
    const std::string path = dir_.write("altered.mslog", damaged);
    const CommandResult verify = meshstep("log verify " + path);
    EXPECT_EQ(verify.status, 1) << verify.out;
    EXPECT_EQ(verify.err.rfind("meshstep: error:", 0), 0u) << verify.err;
    EXPECT_TRUE(contains(verify.err, path)) << verify.err;
    EXPECT_FALSE(contains(verify.out, ": ok:")) << verify.out;
    const CommandResult mesh = meshstep("log mesh " + path + " --step -1 -o " + dir_.file("altered"));
    EXPECT_NE(mesh.status, 0) << mesh.out;
    EXPECT_TRUE(contains(mesh.err, "meshstep: error:")) << mesh.err;
    EXPECT_FALSE(fs::exists(dir_.file("altered.ele")));
  }
}

TEST_F(ReplayCli, FailedRunLeavesNoLog) {
  const std::string collinear = dir_.write("collinear.node", "3 2 0 0\n1 0 0\n2 1 1\n3 2 2\n");
  const CommandResult r = meshstep("triangulate " + collinear + " --record " + log_ + " -o " + prefix_);
  EXPECT_EQ(r.status, 1);
  EXPECT_FALSE(fs::exists(log_));
  EXPECT_FALSE(fs::exists(log_ + ".partial"));
}

}  // namespace
}  // namespace meshstep
