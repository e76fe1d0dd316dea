// Opening, checking and indexing a replay log (see log_reader.hpp).
#include "meshstep/replay/log_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "event_codec.hpp"
#include "format.hpp"
#include "vertex_numbers.hpp"
#include "meshstep/error.hpp"
#include "meshstep/huge_pages.hpp"

namespace meshstep::replay {
namespace {

constexpr std::size_t kCachedBlocks = 8;
constexpr std::size_t kKeyframeCacheBytes = std::size_t{1} << 30;

}  // namespace

struct LogReader::Cache {
  format::Decompressor decompressor;
  std::vector<std::uint8_t> raw;
  std::list<std::pair<std::size_t, DecodedEvents>> blocks;  // most recent first
  std::map<std::size_t, std::vector<FaceRecord>> keyframes;
  std::list<std::size_t> keyframe_order;  // most recent first
  std::size_t keyframe_bytes = 0;
};

LogReader::~LogReader() = default;

LogReader::LogReader(const std::string& path, std::uint64_t keep_writes_bytes)
    : path_(path), vertex_numbers_(std::make_unique<VertexNumbers>()), cache_(std::make_unique<Cache>()) {
  file_ = io::MappedFile(path);
  keep_writes_ = file_.size() <= keep_writes_bytes;
  read_header();
  scan_blocks();
  read_input_fields();
}

// The fields that describe the input, once the parameters are known: the input's vertex
// count bounds the markers and attributes, and the file's size bounds that count (a vertex
// takes a byte of the log at the very least), so a hand-made header cannot make the reader
// allocate more than a small multiple of the file.
void LogReader::read_input_fields() {
  const std::uint64_t inputs = run_.input_vertices;
  const std::size_t limit = static_cast<std::size_t>(std::min<std::uint64_t>(inputs, file_.size()));
  for (const auto& [key, value] : input_fields_) {
    if (value.empty()) continue;
    try {
      if (key == "regions") header_.regions = parse_regions_field(value);
      if (key == "holes") header_.holes = parse_holes_field(value);
      if (key == "vertex_markers") header_.vertex_markers = parse_vertex_markers_field(value, limit);
      if (key == "vertex_attributes")
        std::tie(header_.attributes_per_vertex, header_.vertex_attributes) = parse_vertex_attributes_field(value, limit);
      if (key == "segment_markers") header_.has_segment_markers = value == "1";
      if (key == "segments") header_.segments = parse_segments_field(value, limit);
    } catch (const std::invalid_argument& e) {
      throw InputError(path_, 0, "the header's " + key + " field is malformed: " + e.what());
    }
  }
  input_fields_.clear();
}

std::string LogReader::where(std::size_t block) const {
  const std::uint64_t offset = block < blocks_.size() ? blocks_[block].offset : 0;
  return "events block " + std::to_string(block) + " (byte " + std::to_string(offset) + ")";
}

void LogReader::read_header() {
  const auto fail = [&](const std::string& m) { throw InputError(path_, 0, m); };
  if (file_.size() < 8 || std::memcmp(file_.data(), format::kFileMagic, 8) != 0)
    fail("not a meshstep replay log (it does not begin with \"MSTEPLOG\")");
  if (file_.size() < 16) fail("truncated in its header");
  format_version_ = format::get_le<std::uint32_t>(file_.data() + 8);
  if (format_version_ < format::kOldestReadableVersion || format_version_ > format::kFormatVersion)
    fail("replay log format version " + std::to_string(format_version_) +
         " is not one this meshstep reads (it reads versions " + std::to_string(format::kOldestReadableVersion) +
         " to " + std::to_string(format::kFormatVersion) +
         (format_version_ > format::kFormatVersion ? "; the log may come from a newer meshstep)"
                                                   : "; record the run again with this meshstep)"));
  const std::uint32_t length = format::get_le<std::uint32_t>(file_.data() + 12);
  if (file_.size() < 16 + std::size_t{length} + 8) fail("truncated in its header");
  const std::uint64_t stored = format::get_le<std::uint64_t>(file_.data() + 16 + length);
  if (format::checksum({file_.data(), 16 + std::size_t{length}}) != stored)
    fail("the header is damaged (checksum mismatch)");
  std::map<std::string, std::string*> known = {
      {"program_version", &header_.program_version}, {"input", &header_.input},
      {"input_hash", &header_.input_hash},           {"algorithm", &header_.algorithm},
      {"parameters", &header_.parameters},           {"data_structure", &header_.data_structure},
      {"insertion", &header_.insertion},             {"operations", &header_.operations}};
  const std::uint8_t* p = file_.data() + 16;
  const std::uint8_t* end = p + length;
  while (p < end) {
    if (end - p < 2) fail("the header's fields are malformed");
    const std::uint16_t key_length = format::get_le<std::uint16_t>(p);
    p += 2;
    if (end - p < key_length + 4) fail("the header's fields are malformed");
    const std::string key(reinterpret_cast<const char*>(p), key_length);
    p += key_length;
    const std::uint32_t value_length = format::get_le<std::uint32_t>(p);
    p += 4;
    if (static_cast<std::uint64_t>(end - p) < value_length) fail("the header's fields are malformed");
    // Unknown keys are skipped: a newer writer may add fields within the same version.
    if (const auto it = known.find(key); it != known.end())
      it->second->assign(reinterpret_cast<const char*>(p), value_length);
    if (input_fields_.count(key)) input_fields_[key].assign(reinterpret_cast<const char*>(p), value_length);
    p += value_length;
  }
  blocks_start_ = 16 + std::size_t{length} + 8;
  run_ = read_run_header(header_, path_);
}

// One block of the file, as its header says; and what decoding an events block found.
struct LogReader::BlockSlot {
  std::size_t at = 0, number = 0;
  format::BlockHeader header;
};
struct LogReader::Decoded {
  DecodedEvents events;
  std::string problem;        // why the block is corrupted ("" when it is not)
  bool in_its_bytes = false;  // the checksum or the size: reported before the block's place
};

namespace {

using BlockSlot = LogReader::BlockSlot;
using Decoded = LogReader::Decoded;

// Checks a block's checksum and size, and decodes an events block's events: all a block
// needs that does not depend on the blocks before it, so that two threads can share it.
void decode_block(const std::uint8_t* file, const BlockSlot& slot, std::uint32_t version,
                  format::Decompressor& decompressor, std::vector<std::uint8_t>& raw, Decoded& out) {
  out.problem.clear();
  out.in_its_bytes = false;
  out.events.clear();
  const format::BlockHeader& h = slot.header;
  const std::uint8_t* head = file + slot.at;
  const std::uint8_t* payload = head + format::kBlockHeaderSize;
  if (format::block_checksum(head, {payload, h.stored_size}) != h.checksum) {
    out.problem = "checksum mismatch";
    out.in_its_bytes = true;
    return;
  }
  if (h.raw_size > format::kMaxBlockPayload) {
    out.problem = "block size out of range";
    out.in_its_bytes = true;
    return;
  }
  if (h.kind != format::BlockKind::events) return;
  try {
    decompressor.decompress({payload, h.stored_size}, h.raw_size, raw);
    codec::Decoder decoder(raw.data(), raw.data() + raw.size(), version);
    while (!decoder.done()) {
      try {
        decoder.event(out.events);
      } catch (const codec::FormatError& e) {
        out.problem = "event " + std::to_string(h.first_event + out.events.size()) + " (byte " +
                      std::to_string(decoder.offset()) + " of the block's data): " + e.what();
        return;
      }
    }
  } catch (const std::runtime_error& e) {
    out.problem = e.what();
    return;
  }
  if (out.events.size() != h.count)
    out.problem = "holds " + std::to_string(out.events.size()) + " events, its header says " + std::to_string(h.count);
}

// Blocks decoded at a time: half of them on a helper thread. Their events are held until
// indexed (a few MB), never the whole log's.
constexpr std::size_t kBatch = 8;
// Below this size one thread decodes every block: a thread per batch would cost more than
// it saves (and the tests open small logs of many tiny blocks thousands of times).
constexpr std::size_t kBytesForTwoThreads = std::size_t{4} << 20;

}  // namespace

void LogReader::scan_blocks() {
  // First the headers alone, in file order (cheap): where each block is, up to the first
  // that is damaged or cut short, whose problem is reported once the blocks before it are.
  std::vector<BlockSlot> slots;
  std::string stop;       // why the walk stopped early ("" at the end of the file)
  bool stop_is_corrupt = false;
  for (std::size_t at = blocks_start_; at < file_.size();) {
    const std::string here = "block " + std::to_string(slots.size()) + " of the file (byte " + std::to_string(at) + ")";
    if (file_.size() - at < format::kBlockHeaderSize) {
      stop = "the file ends inside the header of " + here;
      break;
    }
    const std::uint8_t* head = file_.data() + at;
    if (format::get_le<std::uint32_t>(head) != format::kBlockMagic || !format::header_intact(head)) {
      stop = here + ": " +
             (format::get_le<std::uint32_t>(head) != format::kBlockMagic ? "not a block header" : "the block header is damaged") +
             " (the file is corrupted)";
      stop_is_corrupt = true;
      break;
    }
    const format::BlockHeader h = format::parse_block_header(head);
    if (file_.size() - at - format::kBlockHeaderSize < h.stored_size) {
      stop = "the file ends inside " + here;
      break;
    }
    slots.push_back({at, slots.size(), h});
    if (h.kind == format::BlockKind::end) break;
    at += format::kBlockHeaderSize + h.stored_size;
  }

  std::uint64_t declared = 0;
  for (const BlockSlot& slot : slots)
    if (slot.header.kind == format::BlockKind::events) declared += std::min<std::uint64_t>(slot.header.count, UINT32_MAX);
  const std::uint64_t inputs = run_.input_vertices;
  vertex_bound_ = std::min<std::uint64_t>(kInfiniteVertex, std::min<std::uint64_t>(inputs, UINT32_MAX) + declared + 3);

  // Then the blocks in batches: decoded two at a time (this thread and a helper), indexed
  // in file order. A million-point triangulation's log (430 blocks) opens in about half the
  // time it took one thread.
  std::vector<Decoded> decoded(kBatch);
  format::Decompressor helper_decompressor;
  std::vector<std::uint8_t> helper_raw;
  for (std::size_t first = 0; first < slots.size(); first += kBatch) {
    const std::size_t n = std::min(kBatch, slots.size() - first);
    const auto decode = [&](std::size_t start, std::size_t step, format::Decompressor& d, std::vector<std::uint8_t>& raw) {
      for (std::size_t i = start; i < n; i += step) decode_block(file_.data(), slots[first + i], format_version_, d, raw, decoded[i]);
    };
    if (n > 1 && file_.size() >= kBytesForTwoThreads) {
      std::thread helper(decode, 1, 2, std::ref(helper_decompressor), std::ref(helper_raw));
      decode(0, 2, cache_->decompressor, cache_->raw);
      helper.join();
    } else {
      decode(0, 1, cache_->decompressor, cache_->raw);
    }
    for (std::size_t i = 0; i < n; ++i)
      if (index_block(slots[first + i], decoded[i])) return;  // the end block
  }
  if (stop_is_corrupt) throw InputError(path_, 0, stop);
  incomplete_reason_ = !stop.empty() ? stop
                                     : "the file ends after event " + std::to_string(event_count_) +
                                           " without an end block (the run that wrote it did not finish)";
}

bool LogReader::index_block(const BlockSlot& slot, const Decoded& d) {
  const format::BlockHeader& h = slot.header;
  const std::string here =
      "block " + std::to_string(slot.number) + " of the file (byte " + std::to_string(slot.at) + ")";
  const auto corrupt = [&](const std::string& m) { throw InputError(path_, 0, here + ": " + m + " (the file is corrupted)"); };
  if (d.in_its_bytes) corrupt(d.problem);
  try {
    switch (h.kind) {
      case format::BlockKind::events:
        if (h.first_event != event_count_)
          corrupt("starts at event " + std::to_string(h.first_event) + " but " + std::to_string(event_count_) +
                  " events come before it");
        if (!d.problem.empty()) corrupt(d.problem);
        blocks_.push_back({h.first_event, h.count, h.mesh_hash, slot.at, h.stored_size, h.raw_size});
        index_events(blocks_.size() - 1, d.events);
        return false;
      case format::BlockKind::keyframe:
        if (h.first_event != event_count_) corrupt("keyframe out of place");
        keyframes_.push_back({h.first_event, h.count, h.mesh_hash, slot.at, h.stored_size, h.raw_size});
        return false;
      case format::BlockKind::end:
        read_end_block(file_.data() + slot.at + format::kBlockHeaderSize, h.stored_size, h.raw_size);
        final_hash_ = h.mesh_hash;
        // A finished run ends with a keyframe of the algorithm's final mesh.
        if (keyframes_.empty() || keyframes_.back().event != event_count_ || keyframes_.back().mesh_hash != final_hash_)
          corrupt("the keyframe of the final mesh is missing or does not match the end block");
        complete_ = true;
        if (slot.at + format::kBlockHeaderSize + h.stored_size != file_.size()) corrupt("data after the end block");
        return true;
      default: corrupt("unknown block kind " + std::to_string(static_cast<int>(h.kind)));
    }
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e)) throw;
    corrupt(e.what());
  }
  return false;
}

void LogReader::index_events(std::size_t block, const DecodedEvents& events) {
  for (std::size_t i = 0; i < events.size(); ++i) {
    const std::uint64_t e = event_count_ + i;
    const EventHead& h = events.heads[i];
    ++counts_[static_cast<std::size_t>(h.type)];
    for (const SlotWrite& w : events.writes_of(i)) {
      if (w.slot > slot_bound_)
        throw InputError(path_, 0, where(block) + ": event " + std::to_string(e) + " writes face slot " +
                                       std::to_string(w.slot) + ", but only " + std::to_string(slot_bound_) +
                                       " slots were made before it (the file is corrupted)");
      if (w.slot == slot_bound_) ++slot_bound_;
      for (const FaceRecord* r : {&w.before, &w.after})
        for (const VertexId v : r->v)
          if (v != kNone && v != kInfiniteVertex && v >= vertex_bound_)
            throw InputError(path_, 0, where(block) + ": event " + std::to_string(e) + " names vertex " +
                                           std::to_string(v) + ", more than the log can introduce (the file is corrupted)");
    }
    if (keep_writes_) {
      const auto w = events.writes_of(i);
      grow_huge(writes_, w.size());
      grow_huge(write_end_);
      writes_.insert(writes_.end(), w.begin(), w.end());
      write_end_.push_back(writes_.size());
    }
    if (h.type == EventType::step_begin) {
      grow_huge(step_starts_);
      grow_huge(step_kinds_);
      step_starts_.push_back(e);
      step_kinds_.push_back(static_cast<StepKind>(h.code));
    }
    if (h.type == EventType::phase_begin) phases_.push_back({static_cast<Phase>(h.code), e, kNoEnd});
    if (h.type == EventType::phase_end) {
      // The innermost phase of that kind still open: phases nest, never interleave.
      for (auto p = phases_.rbegin(); p != phases_.rend(); ++p)
        if (p->phase == static_cast<Phase>(h.code) && p->end == kNoEnd) {
          p->end = e + 1;
          break;
        }
    }
    if (h.type == EventType::vertex || h.type == EventType::duplicate) {
      const VertexId v = h.ids[0];
      if (v >= vertex_bound_)
        throw InputError(path_, 0, where(block) + ": event " + std::to_string(e) + " introduces vertex " + std::to_string(v) +
                                       ", more than the log can introduce (the file is corrupted)");
      if (v >= vertices_.size()) resize_huge(vertices_, std::size_t{v} + 1, VertexInfo{{0, 0}, kNone, kNone, kNone, UINT64_MAX});
      VertexInfo& info = vertices_[v];
      info.point = h.point;
      info.event = e;
      if (h.type == EventType::vertex) {
        info.input_index = h.ids[1];
      } else {
        info.same_as = h.ids[1];
        info.input_index = h.ids[2];
      }
    }
    if (h.type == EventType::elevation) {
      const VertexId v = h.ids[0];
      if (v >= vertices_.size() || vertices_[v].event == kNone || !std::isfinite(h.value))
        throw InputError(path_, 0, where(block) + ": event " + std::to_string(e) + " gives vertex " +
                                       std::to_string(v) + (v >= vertices_.size() || vertices_[v].event == kNone
                                                                ? " a height before it is introduced"
                                                                : " a height that is not a number") +
                                       " (the file is corrupted)");
      vertices_[v].z = h.value;
    }
    if (h.type == EventType::remove_vertex) {
      const VertexId v = h.ids[0];
      if (v >= vertices_.size() || vertices_[v].removed != UINT64_MAX)
        throw InputError(path_, 0, where(block) + ": event " + std::to_string(e) + " removes vertex " +
                                       std::to_string(v) + ", which is not there to remove");
      vertices_[v].removed = e;
    }
  }
  event_count_ += events.size();
}

void LogReader::read_end_block(const std::uint8_t* payload, std::size_t stored, std::size_t raw_size) {
  std::vector<std::uint8_t> raw;
  cache_->decompressor.decompress({payload, stored}, raw_size, raw);
  const std::size_t types = format::event_type_count(format_version_);
  if (raw.size() < 16 + 8 * types) throw std::runtime_error("end block too short");
  const auto events = format::get_le<std::uint64_t>(raw.data());
  const auto steps = format::get_le<std::uint64_t>(raw.data() + 8);
  bool same = events == event_count_ && steps == step_starts_.size();
  for (std::size_t t = 0; t < types; ++t)
    same = same && format::get_le<std::uint64_t>(raw.data() + 16 + 8 * t) == counts_[t];
  if (!same) throw std::runtime_error("the end block's counts do not match the events in the file");
}

std::uint64_t LogReader::step_start(std::uint64_t k) const {
  return k < step_starts_.size() ? step_starts_[k] : event_count_;
}

std::uint64_t LogReader::step_of_event(std::uint64_t e) const {
  const auto it = std::upper_bound(step_starts_.begin(), step_starts_.end(), e);
  if (it == step_starts_.begin()) return step_starts_.size();
  return static_cast<std::uint64_t>(it - step_starts_.begin()) - 1;
}

std::uint64_t LogReader::completed_steps_at(std::uint64_t position) const {
  if (step_count() == 0 || position <= step_start(0)) return 0;
  // Steps whose begin came before the position, minus the one still open (if any).
  const std::uint64_t begun = step_of_event(position - 1) + 1;
  return position == step_start(begun) ? begun : begun - 1;
}

std::uint64_t LogReader::next_step_boundary(std::uint64_t position) const {
  if (position >= event_count_) return event_count_;
  return step_start(position < step_start(0) ? 0 : step_of_event(position) + 1);
}

std::uint64_t LogReader::prev_step_boundary(std::uint64_t position) const {
  if (position == 0 || step_count() == 0 || position <= step_start(0)) return 0;
  return step_start(step_of_event(position - 1));  // the start of the step holding the last event
}

std::size_t LogReader::block_of_event(std::uint64_t e) const {
  const auto it = std::upper_bound(blocks_.begin(), blocks_.end(), e,
                                   [](std::uint64_t x, const BlockInfo& b) { return x < b.first_event; });
  return static_cast<std::size_t>(it - blocks_.begin()) - 1;
}

const DecodedEvents& LogReader::block_events(std::size_t block) const {
  auto& cached = cache_->blocks;
  for (auto it = cached.begin(); it != cached.end(); ++it)
    if (it->first == block) {
      cached.splice(cached.begin(), cached, it);
      return cached.front().second;
    }
  DecodedEvents events;
  if (cached.size() >= kCachedBlocks) {
    events = std::move(cached.back().second);  // reuse its buffers
    events.clear();
    cached.pop_back();
  }
  const BlockInfo& b = blocks_[block];
  const std::uint8_t* payload = file_.data() + b.offset + format::kBlockHeaderSize;
  cache_->decompressor.decompress({payload, b.stored_size}, b.raw_size, cache_->raw);
  codec::Decoder decoder(cache_->raw.data(), cache_->raw.data() + cache_->raw.size(), format_version_);
  while (!decoder.done()) decoder.event(events);  // checked when the file was opened
  cached.emplace_front(block, std::move(events));
  return cached.front().second;
}

std::span<const SlotWrite> LogReader::writes_from_blocks(std::uint64_t e) const {
  std::size_t b = last_block_;
  if (b >= blocks_.size() || e < blocks_[b].first_event || e >= blocks_[b].first_event + blocks_[b].event_count)
    b = last_block_ = block_of_event(e);
  return block_events(b).writes_of(e - blocks_[b].first_event);
}

Event LogReader::event(std::uint64_t e) const {
  const std::size_t b = block_of_event(e);
  return block_events(b)[e - blocks_[b].first_event];
}

const std::vector<FaceRecord>& LogReader::keyframe(std::size_t j) const {
  if (const auto it = cache_->keyframes.find(j); it != cache_->keyframes.end()) {
    cache_->keyframe_order.remove(j);
    cache_->keyframe_order.push_front(j);
    return it->second;
  }
  const KeyframeInfo& k = keyframes_[j];
  const std::uint8_t* payload = file_.data() + k.offset + format::kBlockHeaderSize;
  std::vector<std::uint8_t> raw;
  std::vector<FaceRecord> slots;
  try {
    cache_->decompressor.decompress({payload, k.stored_size}, k.raw_size, raw);
    slots = codec::decode_keyframe(raw, k.slot_count);
  } catch (const std::runtime_error& e) {
    throw InputError(path_, 0, "keyframe at byte " + std::to_string(k.offset) + ": " + e.what() +
                                   " (the file is corrupted)");
  }
  const std::size_t bytes = slots.size() * sizeof(FaceRecord);
  while (!cache_->keyframe_order.empty() && cache_->keyframe_bytes + bytes > kKeyframeCacheBytes) {
    const std::size_t old = cache_->keyframe_order.back();
    cache_->keyframe_order.pop_back();
    cache_->keyframe_bytes -= cache_->keyframes[old].size() * sizeof(FaceRecord);
    cache_->keyframes.erase(old);
  }
  cache_->keyframe_bytes += bytes;
  cache_->keyframe_order.push_front(j);
  return cache_->keyframes[j] = std::move(slots);
}

}  // namespace meshstep::replay
