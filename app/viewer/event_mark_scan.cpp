#include "event_mark_scan.hpp"

#include <exception>
#include <utility>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer {

EventMarkScan::~EventMarkScan() {
  stop_.store(true, std::memory_order_relaxed);
  if (thread_.joinable()) thread_.join();
}

void EventMarkScan::start(const std::string& log_path) {
  if (thread_.joinable()) return;
  thread_ = std::thread([this, log_path] {
    try {
      const replay::LogReader reader(log_path);
      const std::uint64_t events = reader.event_count();
      for (std::size_t b = 0; b < reader.blocks().size() && !stop_.load(std::memory_order_relaxed); ++b) {
        const replay::DecodedEvents& block = reader.block_events(b);
        const std::uint64_t first = reader.blocks()[b].first_event;
        for (std::size_t i = 0; i < block.size() && first + i < events; ++i) {
          // Only these types can be marked: the others are passed over without building them.
          const replay::EventType type = block.heads[i].type;
          if (type != replay::EventType::flip && type != replay::EventType::encroached &&
              type != replay::EventType::cavity)
            continue;
          const replay::Event e = block[i];
          for (std::size_t m = 0; m < kMarkCount; ++m)
            if (!marks_steps(static_cast<Mark>(m)) && marks_event(static_cast<Mark>(m), e))
              positions_[m].push_back(first + i + 1);
        }
      }
    } catch (const std::exception& e) {
      for (std::vector<std::uint64_t>& p : positions_) p.clear();
      error_ = e.what();
    }
    ready_.store(true, std::memory_order_release);
  });
}

EventMarkScan::Positions EventMarkScan::take() {
  Positions out;
  if (ready()) std::swap(out, positions_);
  return out;
}

}  // namespace meshstep::viewer
