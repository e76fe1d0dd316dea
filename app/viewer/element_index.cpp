#include "element_index.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <utility>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer {

const SegmentTable ElementIndex::kNoSegments;

ElementIndex::~ElementIndex() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void ElementIndex::reset() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  stop_ = false;
  ready_.store(false, std::memory_order_release);
  vertices_ = {};
  slots_ = {};
  segments_ = {};
  seconds_ = 0.0;
  error_.clear();
}

void ElementIndex::build(const std::string& log_path) {
  reset();
  thread_ = std::thread([this, log_path] {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      index(log_path);
    } catch (const std::exception& e) {
      error_ = e.what();
      vertices_ = {};
      slots_ = {};
      segments_ = {};
    }
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ready_.store(true, std::memory_order_release);
  });
}

namespace {

// Does the event rewrite faces around vertices it does not name?
bool indexes_its_corners(replay::EventType type) {
  return type == replay::EventType::cavity || type == replay::EventType::remove_vertex;
}

// Room for the pass's pairs, from the log's counts by event type: at most this many
// vertices and writes an event of each type has (a cavity, a guess: most have fewer). The
// pairs then never move as they grow (at a million points, growing cost a third of the
// pass), and room left over is never touched, so costs no memory.
std::pair<std::size_t, std::size_t> room_for_pairs(const replay::LogReader& log) {
  using replay::EventType;
  const auto& n = log.counts_by_type();
  const auto count = [&](EventType t) { return static_cast<std::size_t>(n[static_cast<std::size_t>(t)]); };
  const std::size_t vertices = 3 * count(EventType::init) + count(EventType::split_face) + 3 * count(EventType::split_edge) +
                               4 * count(EventType::flip) + 8 * count(EventType::cavity) + 2 * count(EventType::constrain) +
                               4 * count(EventType::remove_vertex);
  const std::size_t writes = 8 * count(EventType::init) + 3 * count(EventType::split_face) + 4 * count(EventType::split_edge) +
                             2 * count(EventType::flip) + 14 * count(EventType::cavity) + 2 * count(EventType::constrain) +
                             count(EventType::remove_face) + 3 * count(EventType::remove_vertex);
  return {vertices, writes};
}

}  // namespace

void ElementIndex::index(const std::string& log_path) {
  // Writes are read from the blocks as the pass goes: keeping them all decoded (what the
  // viewer's own reader does for small logs) would only cost memory here.
  const replay::LogReader log(log_path, 0);
  const std::size_t vertex_count = log.vertices().size();
  // One pass collects (vertex, event) and (slot, event) pairs; counting sorts make the rows.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> vertex_pairs, slot_pairs;
  std::vector<std::uint32_t> named;  // one event's vertices, each once
  std::uint32_t slot_count = 0;
  const auto [vertex_room, slot_room] = room_for_pairs(log);
  vertex_pairs.reserve(vertex_room);
  slot_pairs.reserve(slot_room);
  for (std::size_t b = 0; b < log.blocks().size() && !stop_; ++b) {
    const replay::DecodedEvents& block = log.block_events(b);
    const auto first = static_cast<std::uint32_t>(log.blocks()[b].first_event);
    for (std::size_t i = 0; i < block.size(); ++i) {
      const replay::Event ev = block[i];
      const auto e = first + static_cast<std::uint32_t>(i);
      segments_.add(ev, e);
      const replay::EventSchema& schema = replay::schema(ev.type);
      if (!schema.changes_mesh()) continue;
      named.clear();
      for (std::size_t k = 0; k < schema.id_count; ++k)
        if (schema.id_kinds[k] == replay::IdKind::vertex && ev.ids[k] < vertex_count) named.push_back(ev.ids[k]);
      if (indexes_its_corners(ev.type))
        for (const replay::SlotWrite& w : ev.writes)
          for (const replay::FaceRecord* f : {&w.before, &w.after})
            for (const VertexId v : f->v)
              if (v < vertex_count) named.push_back(v);
      std::sort(named.begin(), named.end());
      named.erase(std::unique(named.begin(), named.end()), named.end());
      for (const VertexId v : named) vertex_pairs.emplace_back(v, e);
      for (const replay::SlotWrite& w : ev.writes) {
        if (!slot_pairs.empty() && slot_pairs.back() == std::pair{w.slot, e}) continue;  // twice in one event
        slot_pairs.emplace_back(w.slot, e);
        slot_count = std::max(slot_count, w.slot + 1);
      }
    }
  }
  vertices_ = Rows<std::uint32_t>::from_pairs(vertex_pairs, vertex_count);
  vertex_pairs = {};
  slots_ = Rows<std::uint32_t>::from_pairs(slot_pairs, slot_count);
  segments_.finish();
}

}  // namespace meshstep::viewer
