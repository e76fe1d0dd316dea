#include "element_index.hpp"

#include <chrono>
#include <exception>
#include <utility>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer {

ElementIndex::~ElementIndex() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void ElementIndex::build(const std::string& log_path) {
  thread_ = std::thread([this, log_path] {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      const replay::LogReader log(log_path);
      // One pass collects (vertex, event) pairs; a counting sort by vertex makes the rows.
      std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
      const std::size_t vertices = log.vertices().size();
      for (std::uint64_t e = 0; e < log.event_count() && !stop_; ++e) {
        const replay::Event ev = log.event(e);
        const replay::EventSchema& schema = replay::schema(ev.type);
        if (!schema.changes_mesh()) continue;
        for (std::size_t i = 0; i < schema.id_count; ++i)
          if (schema.id_kinds[i] == replay::IdKind::vertex && ev.ids[i] < vertices)
            pairs.emplace_back(ev.ids[i], static_cast<std::uint32_t>(e));
      }
      offsets_.assign(vertices + 1, 0);
      for (const auto& p : pairs) ++offsets_[p.first + 1];
      for (std::size_t v = 0; v < vertices; ++v) offsets_[v + 1] += offsets_[v];
      events_.resize(pairs.size());
      std::vector<std::uint32_t> next(offsets_.begin(), offsets_.end() - 1);
      for (const auto& p : pairs) events_[next[p.first]++] = p.second;  // events stay in order
    } catch (const std::exception& e) {
      error_ = e.what();
      offsets_.clear();
      events_.clear();
    }
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ready_.store(true, std::memory_order_release);
  });
}

std::span<const std::uint32_t> ElementIndex::events_of_vertex(std::uint32_t v) const {
  if (!ready() || v + 1 >= offsets_.size()) return {};
  return {events_.data() + offsets_[v], offsets_[v + 1] - offsets_[v]};
}

}  // namespace meshstep::viewer
