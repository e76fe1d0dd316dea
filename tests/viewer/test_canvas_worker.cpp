// The canvas worker in process: it draws the exact moment asked for last (not one in
// between), hands each picture over once, and its scene, words and pixels are those the
// main thread makes of the same moment.
#include <gtest/gtest.h>

#include <memory>

#include "canvas_worker.hpp"
#include "golden_runs.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"

namespace meshstep::viewer {
namespace {

class CanvasWorkerTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    try {
      context_ = render::make_offscreen_context(GetParam());
    } catch (const render::GlUnavailable& e) {
      GTEST_SKIP() << e.what();
    }
    log_ = golden::lesson_run("--algorithm offcenter --min-angle 30");
    ASSERT_NE(log_, nullptr);
  }

  CanvasRequest at(std::uint64_t position) const {
    CanvasRequest r;
    r.position = position;
    r.color_by = scene::ColorBy::angle;
    r.center = {0.5, 0.5};
    r.pixels_per_unit = 300.0;
    r.width = 320;
    r.height = 240;
    return r;
  }

  std::unique_ptr<render::GlContext> context_;
  const replay::LogReader* log_ = nullptr;
};

TEST_P(CanvasWorkerTest, DrawsTheLastMomentAskedForExactly) {
  CanvasWorker worker(log_->path(), GetParam());
  CanvasPicture picture;
  EXPECT_FALSE(worker.take(picture)) << "nothing asked for yet";
  // Many requests in a row, as a drag along the timeline makes: the last one wins.
  for (std::uint64_t k = 1; k <= 40; ++k) worker.request(at(log_->step_start(k)));
  worker.wait_until_drawn();
  ASSERT_EQ(worker.error(), "");
  ASSERT_TRUE(worker.take(picture));
  EXPECT_FALSE(worker.take(picture)) << "a picture is handed over once";
  EXPECT_FALSE(worker.drawing());
  EXPECT_EQ(picture.request, at(log_->step_start(40)));
  EXPECT_EQ(picture.moment.position, log_->step_start(40));
  ASSERT_EQ(picture.image.width, 320);
  ASSERT_EQ(picture.image.height, 240);

  // The same moment made on this thread: the same scene, words and pixels.
  std::unique_ptr<Session> here = Session::open_log(log_->path());
  here->seek(log_->step_start(40));
  here->set_color_by(scene::ColorBy::angle);
  const scene::Scene& expected = here->scene();
  EXPECT_EQ(picture.moment.scene.mesh.triangles, expected.mesh.triangles);
  EXPECT_EQ(picture.moment.scene.caption, expected.caption);
  EXPECT_EQ(picture.moment.explanation.heading, here->explanation().heading);
  EXPECT_EQ(picture.moment.explanation.lines, here->explanation().lines);
  context_->make_current();
  render::Renderer renderer;
  renderer.render(expected, at(0).camera());
  const scene::ImageDiff diff = scene::compare_images(renderer.read_pixels(), picture.image, 0);
  EXPECT_TRUE(diff.same_size);
  EXPECT_EQ(diff.differing_pixels, 0u);

  // Another camera over the same moment: a new picture, the same moment's content.
  CanvasRequest panned = at(log_->step_start(40));
  panned.center = {0.4, 0.5};
  const std::size_t serial = picture.moment.serial;
  worker.request(panned);
  worker.wait_until_drawn();
  ASSERT_TRUE(worker.take(picture));
  EXPECT_EQ(picture.request, panned);
  EXPECT_EQ(picture.moment.serial, serial) << "a pan builds no new scene";
  // Another position: a new scene.
  worker.request(at(log_->step_start(3)));
  worker.wait_until_drawn();
  ASSERT_TRUE(worker.take(picture));
  EXPECT_NE(picture.moment.serial, serial);
  EXPECT_EQ(picture.moment.position, log_->step_start(3));
}

TEST_P(CanvasWorkerTest, ANewMomentOfABigMeshIsApproximateFirstAndExactAtRest) {
  // Every mesh counts as big here (the lesson's is small): each new request is drawn with
  // the level of detail first, then, nothing newer being asked, exactly.
  CanvasWorker worker(log_->path(), GetParam(), CanvasWorker::Follow::fixed_log, 1);
  CanvasPicture picture;
  worker.request(at(log_->step_start(40)));
  worker.wait_until_drawn();
  ASSERT_EQ(worker.error(), "");
  EXPECT_EQ(worker.approximate_pictures(), 1u);
  ASSERT_TRUE(worker.take(picture));
  EXPECT_FALSE(picture.approximate) << "the picture at rest is exact";
  EXPECT_FALSE(worker.drawing());

  // Its pixels are the exact picture's.
  std::unique_ptr<Session> here = Session::open_log(log_->path());
  here->seek(log_->step_start(40));
  here->set_color_by(scene::ColorBy::angle);
  context_->make_current();
  render::Renderer renderer;
  renderer.render(here->scene(), at(0).camera());
  EXPECT_EQ(scene::compare_images(renderer.read_pixels(), picture.image, 0).differing_pixels, 0u);
  // The approximate picture said so on itself.
  renderer.render(here->scene(), at(0).camera(), 1, render::Detail::approximate, kApproximateNote);
  EXPECT_GT(scene::compare_images(renderer.read_pixels(), picture.image, 5).differing_pixels, 0u)
      << "the note is drawn on an approximate picture";
}

TEST_P(CanvasWorkerTest, AnUnreadableLogIsReportedNotThrown) {
  CanvasWorker worker("/nonexistent/run.mslog", GetParam());
  worker.request(at(0));
  worker.wait_until_drawn();
  EXPECT_NE(worker.error().find("/nonexistent/run.mslog"), std::string::npos) << worker.error();
  EXPECT_FALSE(worker.drawing());
}

INSTANTIATE_TEST_SUITE_P(Backends, CanvasWorkerTest, ::testing::Values("egl", "osmesa"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace meshstep::viewer
