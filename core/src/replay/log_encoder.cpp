// Raw events to encoded, compressed blocks (see log_encoder.hpp).
#include "log_encoder.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include "meshstep/replay/mesh_hash.hpp"

namespace meshstep::replay {
namespace {

double take_double(std::span<const std::uint32_t>::iterator& it) {
  const std::uint64_t lo = *it++, hi = *it++;
  return std::bit_cast<double>(lo | (hi << 32));
}

// The version a writer asked for (0: the current one); throws for one it cannot write.
std::uint32_t version_to_write(std::uint32_t asked) {
  if (asked == 0) return format::kFormatVersion;
  if (asked < format::kOldestReadableVersion || asked > format::kFormatVersion)
    throw std::invalid_argument("replay log format version " + std::to_string(asked) + " cannot be written (" +
                                std::to_string(format::kOldestReadableVersion) + " to " +
                                std::to_string(format::kFormatVersion) + " can)");
  return asked;
}

}  // namespace

LogEncoder::LogEncoder(const LogWriterOptions& options, BlockOut out)
    : options_(options), version_(version_to_write(options.format_version)), out_(std::move(out)),
      compressor_(options.zstd_level), encoder_(version_) {
  block_.resize(options_.block_bytes + 65536);
}

namespace {

FaceRecord record_at(std::span<const std::uint32_t> words, std::size_t i) {
  FaceRecord r;
  r.v = {words[5 * i + 1], words[5 * i + 2], words[5 * i + 3]};
  r.constrained = static_cast<std::uint8_t>(words[5 * i + 4]);
  return r;
}

}  // namespace

// `before` and `after` hold (slot, v0, v1, v2, flags) quintuples, each slot at most once
// per list; a slot in one list only was dead on the other side.
void LogEncoder::pair_writes(std::span<const std::uint32_t> before, std::span<const std::uint32_t> after) {
  writes_.clear();
  const std::size_t nb = before.size() / 5, na = after.size() / 5;
  for (std::size_t i = 0; i < nb; ++i) writes_.push_back({before[5 * i], record_at(before, i), FaceRecord{}});
  // Changes replace a handful of faces: pairing by linear search beats any index up to
  // cavities of a few dozen faces, and large cavities are rare.
  for (std::size_t j = 0; j < na; ++j) {
    const FaceId slot = after[5 * j];
    SlotWrite* match = nullptr;
    for (std::size_t i = 0; i < nb && !match; ++i)
      if (writes_[i].slot == slot) match = &writes_[i];
    if (match) match->after = record_at(after, j);
    else writes_.push_back({slot, FaceRecord{}, record_at(after, j)});
  }
}

void LogEncoder::consume(std::span<const std::uint32_t> words) {
  auto it = words.begin();
  while (it != words.end()) it = parse(it, words.end());
}

[[gnu::flatten]] std::span<const std::uint32_t>::iterator LogEncoder::parse(
    std::span<const std::uint32_t>::iterator it, std::span<const std::uint32_t>::iterator end) {
  (void)end;  // the recorder writes whole events; batches never split one
  if (*it == kKeyframeWord) return keyframe(it + 1);
  if ((*it & 0xFF) == kFlipWord) return flip(it);
  if (*it == kSplitFaceWord) return split_face(it);
  Event e;
  const std::uint32_t head = *it++;
  e.type = static_cast<EventType>(head & 0xFF);
  e.code = static_cast<std::uint8_t>(head >> 8);
  const EventSchema& s = schema(e.type);
  for (int i = 0; i < s.id_count; ++i) e.ids[i] = *it++;
  if (s.has_point) {
    const double x = take_double(it);
    e.point = {x, take_double(it)};
  }
  if (s.has_value) e.value = take_double(it);
  if (s.has_list) {  // read in place: the batch outlives the event's encoding
    e.list = std::span<const std::uint32_t>(it + 1, *it);
    it += 1 + e.list.size();
  }
  if (s.has_points) {
    const std::uint32_t n = *it++;
    points_.clear();
    for (std::uint32_t i = 0; i < n; ++i) {
      const double x = take_double(it);
      points_.push_back({x, take_double(it)});
    }
    e.points = points_;
  }
  if (s.has_writes) {
    const std::size_t nb = *it++;
    const std::span<const std::uint32_t> before(&*it, 5 * nb);
    it += 5 * nb;
    const std::size_t na = *it++;
    const std::span<const std::uint32_t> after(&*it, 5 * na);
    it += 5 * na;
    pair_writes(before, after);
    e.writes = writes_;
  }

  finish_event(e);
  return it;
}

void LogEncoder::finish_event(const Event& e) {
  const std::size_t room = codec::Encoder::max_bytes(e);
  if (block_used_ + room > block_.size()) block_.resize(2 * (block_used_ + room));
  block_used_ = static_cast<std::size_t>(encoder_.event(e, block_.data() + block_used_) - block_.data());
  count_event(e.type);
}

void LogEncoder::count_event(EventType type) {
  if (static_cast<std::size_t>(type) >= format::event_type_count(version_))
    throw std::invalid_argument(std::string("a replay log of format ") + std::to_string(version_) + " cannot hold " +
                                name(type) + " events");
  ++stats_.events;
  ++stats_.by_type[static_cast<std::size_t>(type)];
  if (type == EventType::step_begin) {
    ++stats_.steps;
    ++block_steps_;
  }
  if (block_used_ >= options_.block_bytes) flush_events();
}

void LogEncoder::emit(format::BlockHeader header, std::span<const std::uint8_t> raw, Compression compression) {
  std::span<const std::uint8_t> payload = raw;
  if (compression == Compression::zstd && (options_.compress || version_ < format::kCompactVersion)) {
    compressor_.compress(raw, stored_);
    if (stored_.size() < raw.size()) payload = stored_;
  }
  header.raw_size = static_cast<std::uint32_t>(raw.size());
  header.stored_size = static_cast<std::uint32_t>(payload.size());
  std::uint8_t bytes[format::kBlockHeaderSize];
  format::serialize(header, bytes);
  header.checksum = format::block_checksum(bytes, payload);
  out_(header, payload);
  ++stats_.blocks;
  stats_.bytes += format::kBlockHeaderSize + payload.size();
}

void LogEncoder::flush_events() {
  const std::uint64_t count = stats_.events - block_first_event_;
  if (count == 0) return;
  format::BlockHeader h;
  h.kind = format::BlockKind::events;
  h.first_event = block_first_event_;
  h.count = count;
  h.steps = block_steps_;
  emit(h, {block_.data(), block_used_});
  block_used_ = 0;
  encoder_.reset();
  block_first_event_ = stats_.events;
  block_steps_ = 0;
}

// Packed flips and split_faces (event_sink.hpp) are stored as they are packed: the bulk of every run costs a
// few bytes copied.
std::span<const std::uint32_t>::iterator LogEncoder::flip(std::span<const std::uint32_t>::iterator it) {
  if (block_used_ + codec::Encoder::kMaxFlipBytes > block_.size()) block_.resize(2 * block_.size());
  const auto code = static_cast<std::uint8_t>(it[0] >> 8);
  block_used_ = static_cast<std::size_t>(
      encoder_.flip(code, {it[1], it[2], it[3], it[4]}, {it[5], it[6], it[7], it[8]}, it[9],
                    block_.data() + block_used_) -
      block_.data());
  count_event(EventType::flip);
  return it + 10;
}

std::span<const std::uint32_t>::iterator LogEncoder::split_face(std::span<const std::uint32_t>::iterator it) {
  if (block_used_ + codec::Encoder::kMaxSplitFaceBytes > block_.size()) block_.resize(2 * block_.size());
  block_used_ = static_cast<std::size_t>(
      encoder_.split_face(it[1], {it[2], it[3], it[4]}, it[5], {it[6], it[7], it[8]}, it[9],
                          block_.data() + block_used_) -
      block_.data());
  count_event(EventType::split_face);
  return it + 10;
}

// A keyframe sits between blocks: the events block so far ends where it is taken. Encoded
// straight from the raw words, hashed on the way: a million faces, no copy.
std::span<const std::uint32_t>::iterator LogEncoder::keyframe(std::span<const std::uint32_t>::iterator it) {
  flush_events();
  const std::size_t count = *it++;
  codec::KeyframeEncoder encoder;
  std::uint64_t hash = 0;
  std::size_t used = 0;
  // In chunks, so that the buffer grows with what a keyframe takes (about 8 bytes a face),
  // not with the worst case.
  constexpr std::size_t kChunk = 4096;
  for (std::size_t first = 0; first < count; first += kChunk) {
    const std::size_t n = std::min(kChunk, count - first);
    const std::size_t room = used + n * codec::KeyframeEncoder::kMaxSlotBytes;
    if (keyframe_.size() < room) keyframe_.resize(std::max(room, 2 * keyframe_.size()));
    used = static_cast<std::size_t>(encoder.slots(&*it, n, keyframe_.data() + used, hash) - keyframe_.data());
    it += 4 * n;
  }
  format::BlockHeader h;
  h.kind = format::BlockKind::keyframe;
  h.first_event = stats_.events;
  h.count = count;
  hash_ = hash;  // of the data structure's own faces, not of the events
  h.mesh_hash = hash_;
  const std::uint64_t before = stats_.bytes;
  // Stored as is: the slot layout leaves zstd's fast levels nothing to find (at -20, 15.68 MB
  // of a 2M-face keyframe came out 15.68 MB, after 17 ms at the end of the run).
  emit(h, {keyframe_.data(), used}, Compression::none);
  stats_.keyframe_bytes += stats_.bytes - before;
  ++stats_.keyframes;
  return it;
}

void LogEncoder::finish() {
  flush_events();
  std::vector<std::uint8_t> summary;
  format::put_le(summary, stats_.events);
  format::put_le(summary, stats_.steps);
  for (std::size_t t = 0; t < format::event_type_count(version_); ++t) format::put_le(summary, stats_.by_type[t]);
  format::BlockHeader h;
  h.kind = format::BlockKind::end;
  h.first_event = stats_.events;
  h.count = stats_.steps;
  h.mesh_hash = hash_;
  emit(h, summary);
}

}  // namespace meshstep::replay
