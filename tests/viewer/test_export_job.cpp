// Export from the viewer: the names of the files it writes, and a video of a range of steps
// made by `meshstep export` in the background.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "export_job.hpp"
#include "golden_runs.hpp"
#include "run_cli.hpp"

namespace meshstep::viewer {
namespace {

namespace fs = std::filesystem;

TEST(ViewerExport, NamesFilesBesideTheLog) {
  EXPECT_EQ(export_name("/runs/lesson.mslog", 45, "step", ".png"), "/runs/lesson_step45.png");
  EXPECT_EQ(export_name("lesson.mslog", 3, "window_step", ".png"), "./lesson_window_step3.png");
}

TEST(ViewerExport, WritesAVideoOfARangeInTheBackground) {
  if (!testing::ffmpeg_works()) GTEST_SKIP() << "ffmpeg is not installed, or does not start";
  const replay::LogReader* log = golden::lesson_run("--algorithm offcenter --min-angle 30");
  ASSERT_NE(log, nullptr);
  const fs::path out = fs::temp_directory_path() / ("viewer_export_" + std::to_string(::getpid()) + ".mp4");
  ExportJob job(MESHSTEP_BINARY);
  ASSERT_TRUE(job.start(log->path(), out.string(), 10, 20)) << job.status();
  EXPECT_NE(job.status().find("writing"), std::string::npos);
  for (int i = 0; i < 600 && job.running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(job.status(), "wrote " + out.string());
  EXPECT_GT(fs::file_size(out), 1000u);
  fs::remove(out);

  ExportJob missing("/nonexistent/meshstep");
  EXPECT_FALSE(missing.start(log->path(), out.string(), 0, 1));
  EXPECT_NE(missing.status().find("cannot run /nonexistent/meshstep"), std::string::npos) << missing.status();
}

// The export panel's range starts as every step of the run, 0 to n (side_panel.cpp); export
// numbers steps as the viewer does, so that default video is made (it once stopped at n-1).
TEST(ViewerExport, TheDefaultRangeOfEveryStepExports) {
  if (!testing::ffmpeg_works()) GTEST_SKIP() << "ffmpeg is not installed, or does not start";
  const replay::LogReader* log = golden::lesson_run("--algorithm offcenter --min-angle 30");
  ASSERT_NE(log, nullptr);
  const fs::path out = fs::temp_directory_path() / ("viewer_export_all_" + std::to_string(::getpid()) + ".mp4");
  ExportJob job(MESHSTEP_BINARY);
  ASSERT_TRUE(job.start(log->path(), out.string(), 0, log->step_count())) << job.status();
  for (int i = 0; i < 1200 && job.running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(job.status(), "wrote " + out.string());
  EXPECT_TRUE(fs::exists(out));
  fs::remove(out);
}

}  // namespace
}  // namespace meshstep::viewer
