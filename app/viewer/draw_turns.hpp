// Turns at drawing for canvas workers that share a small machine (runs side by side): at
// most `seats` of them draw at once, the others wait for a seat in the order they asked.
//
// Four workers drawing together at the window's priority took 5/8 of two cores from it
// (19 frames a second while scrubbing); below its priority (nice 5) they starved whenever
// the window or the machine's other work wanted the cores (about one new picture a second
// per run). With turns they keep the window's priority but never more than `seats` of them
// want a core at once (their contexts share one llvmpipe rasterizer thread besides), and a
// worker that waited reads the request once its turn comes: what was asked meanwhile
// replaces what woke it, so the wait costs no stale picture.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <algorithm>

namespace meshstep::viewer {

class DrawTurns {
 public:
  explicit DrawTurns(unsigned seats) : seats_(seats == 0 ? 1 : seats) {}
  DrawTurns(const DrawTurns&) = delete;
  DrawTurns& operator=(const DrawTurns&) = delete;

  // Waits for a seat; tickets are served first come, first served (a worker that just drew
  // and asks again queues behind those already waiting: none of them starves).
  void acquire() {
    std::unique_lock lock(mutex_);
    const std::uint64_t ticket = next_ticket_++;
    free_.wait(lock, [&] { return ticket == serving_ && drawing_ < seats_; });
    ++serving_;
    ++drawing_;
    free_.notify_all();  // the next ticket may take another free seat
  }
  // Fewer or more seats from now on (at least one): one more lets a waiting worker in at
  // once; one fewer waits for a drawing one to finish.
  void set_seats(unsigned seats) {
    {
      const std::lock_guard lock(mutex_);
      seats_ = seats == 0 ? 1 : seats;
    }
    free_.notify_all();
  }
  unsigned seats() const {
    const std::lock_guard lock(mutex_);
    return seats_;
  }
  void release() {
    {
      const std::lock_guard lock(mutex_);
      --drawing_;
    }
    free_.notify_all();
  }
  // How many draw now, and how many wait for a seat (tests).
  unsigned drawing() const {
    const std::lock_guard lock(mutex_);
    return drawing_;
  }
  std::uint64_t waiting() const {
    const std::lock_guard lock(mutex_);
    return next_ticket_ - serving_;
  }

  // A seat held for a scope.
  class Seat {
   public:
    explicit Seat(DrawTurns* turns) : turns_(turns) {
      if (turns_) turns_->acquire();
    }
    ~Seat() {
      if (turns_) turns_->release();
    }
    Seat(const Seat&) = delete;
    Seat& operator=(const Seat&) = delete;

   private:
    DrawTurns* turns_;
  };

 private:
  unsigned seats_;
  mutable std::mutex mutex_;
  std::condition_variable free_;
  std::uint64_t next_ticket_ = 0, serving_ = 0;
  unsigned drawing_ = 0;
};

// How many workers may draw, from how late the window's frames are: the pictures take what
// the window leaves. While its frames keep to `on_time` (1/30 s: the frame rate the viewer
// aims at with runs side by side), `most` draw; once they come late, one. The frames'
// intervals are smoothed (a quarter of each new one), so that one slow frame, or a long
// pause of a script, does not swing it.
class FramePace {
 public:
  FramePace(double on_time, unsigned most) : on_time_(on_time), most_(most) {}
  // The time since the frame before (seconds).
  void frame(double interval) {
    interval = std::min(interval, 4.0 * on_time_);
    smoothed_ = smoothed_ < 0 ? interval : 0.75 * smoothed_ + 0.25 * interval;
  }
  unsigned seats() const { return smoothed_ >= 0 && smoothed_ > on_time_ ? 1u : most_; }
  double smoothed() const { return smoothed_; }

 private:
  const double on_time_;
  const unsigned most_;
  double smoothed_ = -1.0;  // none yet
};

}  // namespace meshstep::viewer
