// A live run: an input opened in the viewer runs in the meshstep program while the window
// keeps drawing (the live page, with the mesh written so far), and its whole log opens when
// it ends. The preview worker reads a log still being written as its prefix; an input that
// cannot run is an error with the program's own FILE:LINE message.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "program_support.hpp"
#include "canvas_worker.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "render/gl_context.hpp"

namespace meshstep::viewer {
namespace {

using testing::field;
using testing::has;
using testing::read_text;
using testing::Result;
using testing::run;

namespace fs = std::filesystem;





class LiveRunProgram : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("viewer_live_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  // N points, uniform in the unit square: a run long enough (a few tenths of a second) to
  // be watched while it goes.
  fs::path points(int n) {
    const fs::path node = dir_ / "points.node";
    std::ofstream out(node);
    out << n << " 2 0 0\n";
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    out.precision(17);
    for (int i = 0; i < n; ++i) out << i << ' ' << unit(random) << ' ' << unit(random) << '\n';
    return node;
  }
  Result view(const std::string& input, const std::string& script) {
    const fs::path file = dir_ / "script.txt";
    std::ofstream(file) << script;
    Result r = run(std::string(MESHSTEP_VIEW_BINARY) + " " + input + " --offscreen --gl egl --window 800x600 -q --script " +
                   file.string());
    if (r.status != 0 && has(r.output, "cannot open a window or draw")) r.status = 77;
    return r;
  }
  fs::path dir_;
};

TEST_F(LiveRunProgram, ShowsTheRunAsItGoesThenOpensItsWholeLog) {
  const fs::path node = points(200000);
  const fs::path during = dir_ / "during.json", after = dir_ / "after.json";
  const Result r = view(node.string(), "frames 3\npeek " + during.string() + "\nstate " + after.string() + "\nquit\n");
  if (r.status == 77) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  // Three frames after the start the run is still going: the window drew them.
  const std::string live = read_text(during);
  EXPECT_TRUE(has(live, "\"page\": \"live\"")) << live;
  EXPECT_TRUE(has(live, "\"running\": true")) << live;
  // `state` waited for the end: the whole log is open, at its end, as a recording of the
  // same run made apart shows it.
  const std::string opened = read_text(after);
  const fs::path log = dir_ / "apart.mslog";
  ASSERT_EQ(run(std::string(MESHSTEP_BINARY) + " triangulate " + node.string() + " --record " + log.string() +
                " --no-output -q")
                .status,
            0);
  const replay::LogReader apart(log.string());
  EXPECT_TRUE(has(opened, "\"title\": \"" + node.string() + "\"")) << opened;
  EXPECT_EQ(field(opened, "event_count"), static_cast<long long>(apart.event_count())) << opened;
  EXPECT_EQ(field(opened, "position"), static_cast<long long>(apart.event_count())) << opened;
  EXPECT_EQ(field(opened, "step_count"), static_cast<long long>(apart.step_count())) << opened;
}

// The window's title names what it shows: after a live run, its input, not "start".
TEST_F(LiveRunProgram, TheWindowTitleNamesTheRunOnceItHasEnded) {
  const std::string lesson = std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly";
  const fs::path after = dir_ / "after.json";
  const Result r = view(lesson + " --min-angle 25", "state " + after.string() + "\nquit\n");
  if (r.status == 77) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string opened = read_text(after);
  EXPECT_TRUE(has(opened, "\"window_title\": \"meshstep view: " + lesson + "\"")) << opened;
}

TEST_F(LiveRunProgram, AnInputThatCannotRunIsAnErrorWithItsLine) {
  const fs::path bad = dir_ / "bad.poly";
  std::ofstream(bad) << "3 2 0 0\n0 0 0\n1 1 zero\n2 0 1\n0 0\n0\n";
  const Result r = view(bad.string(), "state " + (dir_ / "s.json").string() + "\nquit\n");
  if (r.status == 77) GTEST_SKIP() << r.output;
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(has(r.output, bad.string() + ":3:")) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "s.json")) << "nothing is looked at after the failure";
}

// A bound no refinement reaches, with a small memory budget: the run stops at the budget,
// as meshstep refine does, and the viewer opens its log as far as it went, saying why.
TEST_F(LiveRunProgram, ARunStoppedAtItsMemoryBudgetIsShownAsFarAsItWent) {
  const std::string plate = std::string(MESHSTEP_ASSETS) + "/examples/plate.poly";
  const fs::path after = dir_ / "after.json", picture = dir_ / "stopped.png";
  const Result r = view(plate + " --min-angle 59 --max-memory 20M",
                        "wait\nframes 3\nwait\nstate " + after.string() + "\nscreenshot " + picture.string() + "\nquit\n");
  if (r.status == 77) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has(r.output, "refinement stopped at the memory budget (20 MB")) << r.output;
  const std::string opened = read_text(after);
  EXPECT_TRUE(has(opened, "\"title\": \"" + plate + "\"")) << opened;
  // 20 MB at 160 bytes a triangle: 131072, and the step that reached it adds one or two.
  EXPECT_GE(field(opened, "triangles"), 131072) << opened;
  EXPECT_LE(field(opened, "triangles"), 131073) << opened;
  EXPECT_EQ(field(opened, "position"), field(opened, "event_count")) << opened;
}

// The preview worker on a log still being written: the prefix written so far, at its end.
TEST_F(LiveRunProgram, PreviewDrawsTheEndOfWhatALogStillBeingWrittenHolds) {
  std::unique_ptr<render::GlContext> context;
  try {
    context = render::make_offscreen_context("egl");
  } catch (const render::GlUnavailable& e) {
    GTEST_SKIP() << e.what();
  }
  // A log of several blocks: half of it holds whole blocks.
  const fs::path log = dir_ / "whole.mslog";
  ASSERT_EQ(run(std::string(MESHSTEP_BINARY) + " triangulate " + points(30000).string() + " --record " + log.string() +
                " --no-output -q")
                .status,
            0);
  const auto whole = std::make_unique<replay::LogReader>(log.string());
  ASSERT_GT(whole->blocks().size(), 4u);
  const fs::path partial = dir_ / "growing.mslog.partial";
  CanvasWorker worker(partial.string(), "egl", CanvasWorker::Follow::growing_log);
  CanvasRequest wanted;
  wanted.position = UINT64_MAX;
  wanted.fit = true;
  wanted.width = 320;
  wanted.height = 240;
  // Not there yet: no picture and no error.
  worker.request(wanted);
  worker.wait_until_drawn();
  CanvasPicture picture;
  EXPECT_FALSE(worker.take(picture));
  EXPECT_EQ(worker.error(), "");
  // Its first half written: the picture of that prefix's end.
  const std::string bytes = read_text(whole->path());
  std::ofstream(partial, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  const replay::LogReader prefix(partial.string());
  ASSERT_GT(prefix.event_count(), 0u);
  ASSERT_LT(prefix.event_count(), whole->event_count());
  wanted.generation = 1;
  worker.request(wanted);
  worker.wait_until_drawn();
  ASSERT_TRUE(worker.take(picture));
  EXPECT_EQ(picture.moment.position, prefix.event_count());
  EXPECT_GT(picture.moment.scene.mesh.triangles.size(), 0u);
  // All of it: the next picture shows the end of the run.
  std::ofstream(partial, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  wanted.generation = 2;
  worker.request(wanted);
  worker.wait_until_drawn();
  ASSERT_TRUE(worker.take(picture));
  EXPECT_EQ(picture.moment.position, whole->event_count());
}

}  // namespace
}  // namespace meshstep::viewer
