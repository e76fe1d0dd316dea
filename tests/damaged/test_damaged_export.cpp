// meshstep export on a log damaged in its events (checksums remade, so that the damage
// is found only where the replay reaches it): the frames of the moments before it are
// drawn by then. The export fails in words and leaves no frame and no folder behind, as
// a failed --video leaves no video: a folder of the first frames would pass for an
// animation of the whole run.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "log_bytes.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using meshstep::testing::CommandResult;
using meshstep::testing::run_meshstep;
using meshstep::testing::TempDir;

std::vector<std::uint8_t> bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  return names;
}

TEST(DamagedExport, FramesOfADamagedLogAreNotLeftBehind) {
  TempDir dir;
  const fs::path log = dir.path() / "lesson.mslog", damaged = dir.path() / "damaged.mslog";
  const CommandResult recorded =
      run_meshstep("refine " + std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly --algorithm offcenter --min-angle 30 "
                   "--record " + log.string() + " -o " + (dir.path() / "lesson").string() + " -q",
                   dir.path());
  ASSERT_EQ(recorded.status, 0) << recorded.err;
  const CommandResult probe = run_meshstep("render " + log.string() + " -o " + (dir.path() / "p.png").string() + " -q",
                                           dir.path());
  if (probe.status != 0) GTEST_SKIP() << "no OpenGL on this machine: " << probe.err;

  // Bytes flipped from the middle of the log on, until the export of one fails part-way:
  // the replay finds the damage at a later step than the first frames'.
  const std::vector<std::uint8_t> original = bytes_of(log);
  std::size_t failed = 0;
  for (std::size_t i = original.size() / 2; i < original.size() && failed < 3; i += 7) {
    std::vector<std::uint8_t> bytes = original;
    bytes[i] ^= 0x5A;
    meshstep::fuzz::fix_checksums(bytes);
    std::ofstream(damaged, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    const fs::path frames = dir.path() / "frames";
    fs::remove_all(frames);
    const CommandResult r =
        run_meshstep("export " + damaged.string() + " --frames " + frames.string() + " --size 40x30 -q", dir.path());
    if (r.status == 0) continue;
    if (r.err.find("inconsistent") == std::string::npos) continue;  // found before any frame
    ++failed;
    EXPECT_EQ(r.status, 1) << "byte " << i << ": " << r.err;
    EXPECT_FALSE(fs::exists(frames)) << "byte " << i << ": " << names_in(frames).size() << " files left";
    // A folder that was there stays as it was.
    fs::create_directory(frames);
    std::ofstream(frames / "notes.txt") << "mine";
    const CommandResult again =
        run_meshstep("export " + damaged.string() + " --frames " + frames.string() + " --size 40x30 -q", dir.path());
    EXPECT_EQ(again.status, 1) << again.err;
    EXPECT_EQ(names_in(frames), std::vector<std::string>{"notes.txt"}) << "byte " << i;
  }
  EXPECT_EQ(failed, 3u) << "no damage found part-way through the export";
}

}  // namespace
