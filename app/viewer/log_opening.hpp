// A recorded run opened on a thread of its own: the log read and its cursor replayed to the
// run's end (Session::open_log, then cursor()), while the window keeps drawing. The
// workbench's live re-meshing ends with such a log: opened on the window's thread, the
// 815,000-triangle one stopped the window for 0.8 s (2.8 s under load). The window asks
// ready() each frame and take()s the session once it is.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "session.hpp"

namespace meshstep::viewer {

class LogOpening {
 public:
  // Starts opening PATH; the session gets TITLE.
  LogOpening(std::string path, std::string title);
  ~LogOpening();  // waits for the thread (an opening no longer wanted ends on its own)
  LogOpening(const LogOpening&) = delete;
  LogOpening& operator=(const LogOpening&) = delete;

  const std::string& path() const { return path_; }
  // Whether the thread has finished (take() then does not wait).
  bool ready() const { return ready_.load(std::memory_order_acquire); }
  // Waits for the thread, then gives the session (null when the log could not be read:
  // error() says why, the InputError's words). Once.
  std::unique_ptr<Session> take();
  const std::string& error() const { return error_; }
  // The thread the log was read and replayed on (for tests: not the caller's).
  std::thread::id opened_on() const { return opened_on_; }

 private:
  void open();

  std::string path_, title_, error_;
  std::unique_ptr<Session> session_;
  std::thread::id opened_on_;
  std::atomic<bool> ready_{false};
  std::thread thread_;  // last: started once every member above is made
};

}  // namespace meshstep::viewer
