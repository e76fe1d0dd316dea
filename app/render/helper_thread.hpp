// One thread kept for splitting a job in two with the calling thread: the CPU's part of the
// level of detail on this project's 2 cores. Starting a thread per job would allocate and
// cost tens of microseconds a frame; this one waits on a condition variable between jobs.
#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>

namespace meshstep::render {

class HelperThread {
 public:
  HelperThread() : thread_([this] { run(); }) {}
  ~HelperThread() {
    {
      const std::lock_guard lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;

  // Runs helper_part() on the helper and caller_part() here, and returns when both are done.
  // Nothing is allocated.
  template <class Helper, class Caller>
  void split(Helper& helper_part, Caller&& caller_part) {
    {
      const std::lock_guard lock(mutex_);
      job_ = &helper_part;
      call_ = [](void* job) { (*static_cast<Helper*>(job))(); };
      pending_ = true;
    }
    wake_.notify_one();
    caller_part();
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return !pending_; });
  }

 private:
  void run() {
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stop_ || pending_; });
      if (stop_) return;
      lock.unlock();
      call_(job_);
      lock.lock();
      pending_ = false;
      done_.notify_one();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  void* job_ = nullptr;
  void (*call_)(void*) = nullptr;
  bool pending_ = false, stop_ = false;
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace meshstep::render
