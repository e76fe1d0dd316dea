// Freeing done on a thread of its own. A big run's session (the arrays of an 815,000-
// triangle log) and its canvas worker (its thread joined, its own copy of the run freed)
// took 370 ms to free under load, on the window's thread, in the frame that showed the
// workbench's next run. Whatever is given to dispose() is destroyed on a thread instead;
// it must need nothing of the window's thread (no GL object of the window's context).
#pragma once

#include <functional>
#include <memory>
#include <thread>

namespace meshstep::viewer {

class Disposal {
 public:
  Disposal() = default;
  ~Disposal();  // waits for what is being freed
  Disposal(const Disposal&) = delete;
  Disposal& operator=(const Disposal&) = delete;

  // Destroys THING on a thread (after the last thing given, which has long ended by then:
  // one run at a time is freed).
  template <class T>
  void dispose(T thing) {
    run([held = std::make_shared<T>(std::move(thing))]() mutable { held.reset(); });
  }

 private:
  void run(std::function<void()> work);
  std::thread thread_;
};

}  // namespace meshstep::viewer
