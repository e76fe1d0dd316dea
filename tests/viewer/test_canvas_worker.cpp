// The canvas worker in process: it draws the exact moment asked for last (not one in
// between), hands each picture over once, and its scene, words and pixels are those the
// main thread makes of the same moment.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "canvas_worker.hpp"
#include "draw_turns.hpp"
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

// A worker that waits for its turn (runs side by side) draws, once the turn comes, the
// newest moment asked for meanwhile: not first the one that woke it.
TEST_P(CanvasWorkerTest, AWorkerWaitingForItsTurnDrawsOnlyTheNewestMoment) {
  DrawTurns turns(1);
  turns.acquire();  // the only seat, held here: the worker waits for it
  CanvasWorker worker(log_->path(), GetParam(), CanvasWorker::Follow::fixed_log, kApproximateFrom,
                      replay::LogReader::kKeepWritesBytes, CanvasWorker::Priority::normal, &turns);
  worker.request(at(log_->step_start(5)));
  // Until the worker queues for the seat (its context and log opened first).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (turns.waiting() == 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_EQ(turns.waiting(), 1u) << worker.error();
  worker.request(at(log_->step_start(40)));  // asked while it waits
  turns.release();
  worker.wait_until_drawn();
  ASSERT_EQ(worker.error(), "");
  CanvasPicture picture;
  ASSERT_TRUE(worker.take(picture));
  EXPECT_EQ(picture.moment.position, log_->step_start(40));
  EXPECT_EQ(worker.pictures_drawn(), 1u) << "the moment asked for before the turn came is not drawn";
  EXPECT_EQ(turns.drawing(), 0u) << "the seat is given back";
}

TEST_P(CanvasWorkerTest, AnUnreadableLogIsReportedNotThrown) {
  CanvasWorker worker("/nonexistent/run.mslog", GetParam());
  worker.request(at(0));
  worker.wait_until_drawn();
  EXPECT_NE(worker.error().find("/nonexistent/run.mslog"), std::string::npos) << worker.error();
  EXPECT_FALSE(worker.drawing());
}

// ---- Turns at drawing (no GL) --------------------------------------------------------

// However many ask at once, no more than the seats draw together, and every one draws.
TEST(DrawTurns, NoMoreDrawAtOnceThanTheSeats) {
  DrawTurns turns(2);
  std::atomic<int> now{0}, most{0}, done{0};
  std::vector<std::thread> workers;
  for (int w = 0; w < 6; ++w)
    workers.emplace_back([&] {
      for (int k = 0; k < 20; ++k) {
        const DrawTurns::Seat seat(&turns);
        const int n = ++now;
        for (int m = most.load(); n > m && !most.compare_exchange_weak(m, n);) {
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        --now;
        ++done;
      }
    });
  for (std::thread& t : workers) t.join();
  EXPECT_EQ(done.load(), 120);
  EXPECT_EQ(most.load(), 2) << "six workers asking together fill both seats, never more";
  EXPECT_EQ(turns.drawing(), 0u);
  EXPECT_EQ(turns.waiting(), 0u);
}

// Seats go first come, first served: one that asks again queues behind those waiting.
TEST(DrawTurns, FirstComeFirstServed) {
  DrawTurns turns(1);
  turns.acquire();
  std::vector<int> order;
  std::mutex order_mutex;
  const auto queue = [&](int who) {
    return std::thread([&, who] {
      const DrawTurns::Seat seat(&turns);
      const std::lock_guard lock(order_mutex);
      order.push_back(who);
    });
  };
  const auto until_waiting = [&](std::uint64_t n) {
    while (turns.waiting() < n) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  };
  std::thread a = queue(1);
  until_waiting(1);
  std::thread b = queue(2);
  until_waiting(2);
  std::thread c = queue(3);
  until_waiting(3);
  turns.release();
  a.join();
  b.join();
  c.join();
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3}));
}

// A seat more lets one that waits in at once; a seat fewer lets none in until one ends.
TEST(DrawTurns, SeatsChangeWhileWorkersWait) {
  DrawTurns turns(1);
  turns.acquire();
  std::thread waiting([&] {
    const DrawTurns::Seat seat(&turns);
  });
  while (turns.waiting() < 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  turns.set_seats(2);
  waiting.join();  // it drew beside the held seat
  EXPECT_EQ(turns.drawing(), 1u);
  turns.acquire();  // two held now
  turns.set_seats(1);
  std::atomic<bool> in{false};
  std::thread late([&] {
    const DrawTurns::Seat seat(&turns);
    in = true;
  });
  while (turns.waiting() < 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  turns.release();  // one still draws: with one seat the late one still waits
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(in.load());
  turns.release();
  late.join();
  EXPECT_TRUE(in.load());
}

// The window's frames decide the seats: on time, the most; late, one; on time again, the
// most (after a few frames: one slow frame or a script's long pause does not swing it).
TEST(FramePace, LateFramesLeaveOneSeat) {
  FramePace pace(1.0 / 30.0, 2);
  EXPECT_EQ(pace.seats(), 2u) << "no frame yet";
  for (int i = 0; i < 10; ++i) pace.frame(0.020);
  EXPECT_EQ(pace.seats(), 2u);
  pace.frame(0.045);
  EXPECT_EQ(pace.seats(), 2u) << "one frame a little late";
  for (int i = 0; i < 10; ++i) pace.frame(0.050);
  EXPECT_EQ(pace.seats(), 1u) << "20 frames a second";
  pace.frame(0.020);
  EXPECT_EQ(pace.seats(), 1u) << "one frame on time";
  for (int i = 0; i < 10; ++i) pace.frame(0.025);
  EXPECT_EQ(pace.seats(), 2u) << "40 frames a second";
  pace.frame(10.0);  // a script's long wait counts as four frames' time at most
  for (int i = 0; i < 6; ++i) pace.frame(0.020);
  EXPECT_EQ(pace.seats(), 2u);
}

INSTANTIATE_TEST_SUITE_P(Backends, CanvasWorkerTest, ::testing::Values("egl", "osmesa"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace meshstep::viewer
