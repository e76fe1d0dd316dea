#include "log_opening.hpp"

#include "meshstep/error.hpp"

namespace meshstep::viewer {

LogOpening::LogOpening(std::string path, std::string title)
    : path_(std::move(path)), title_(std::move(title)), thread_([this] { open(); }) {}

LogOpening::~LogOpening() {
  if (thread_.joinable()) thread_.join();
}

void LogOpening::open() {
  opened_on_ = std::this_thread::get_id();
  try {
    std::unique_ptr<Session> s = Session::open_log(path_);
    s->to_end();   // the mesh made, at the end of its run
    s->cursor();   // replayed here, not on the window's thread at its first frame
    s->set_title(title_);
    session_ = std::move(s);
  } catch (const InputError& e) {
    error_ = e.what();
  } catch (const std::exception& e) {  // std::bad_alloc on a log too big for the memory left
    error_ = path_ + ": " + e.what();
  }
  ready_.store(true, std::memory_order_release);
}

std::unique_ptr<Session> LogOpening::take() {
  if (thread_.joinable()) thread_.join();
  return std::move(session_);
}

}  // namespace meshstep::viewer
