#include "png_frame_writer.hpp"

#include <cstdio>

namespace meshstep::app {

PngFrameWriter::PngFrameWriter(std::string dir, unsigned workers, int compression_level)
    : dir_(std::move(dir)), compression_level_(compression_level) {
  if (workers == 0) workers = std::max(1u, std::thread::hardware_concurrency());
  max_queued_ = 2 * workers;  // enough to keep every worker fed, few enough to bound memory
  for (unsigned i = 0; i < workers; ++i) workers_.emplace_back([this] { work(); });
}

PngFrameWriter::~PngFrameWriter() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  for (std::thread& t : workers_) t.join();
}

std::string PngFrameWriter::frame_name(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06zu.png", index);
  return name;
}

void PngFrameWriter::add(std::size_t index, scene::Image image) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < max_queued_ || error_; });
  if (error_) std::rethrow_exception(error_);
  queue_.push_back({index, std::move(image)});
  changed_.notify_all();
}

void PngFrameWriter::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return (queue_.empty() && busy_ == 0) || error_; });
  if (error_) std::rethrow_exception(error_);
}

void PngFrameWriter::work() {
  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait(lock, [&] { return !queue_.empty() || closing_; });
    if (queue_.empty()) return;  // closing, nothing left
    Job job = std::move(queue_.front());
    queue_.pop_front();
    ++busy_;
    changed_.notify_all();  // room in the queue
    lock.unlock();
    std::exception_ptr failure;
    try {
      scene::write_png(dir_ + "/" + frame_name(job.index), job.image, compression_level_);
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    --busy_;
    if (failure && !error_) error_ = failure;
    changed_.notify_all();
  }
}

}  // namespace meshstep::app
