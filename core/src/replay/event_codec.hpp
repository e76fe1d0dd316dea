// Events to bytes and back, driven by each type's schema.
//
// Vertex ids dominate the data, and most of them repeat ones just written: a flip names
// the vertex being inserted and the edge the previous change made. So a vertex is written
// as one byte when it is in a small direct-mapped cache of recent vertices (slot v % 64),
// and otherwise as the difference from the last vertex written in full. Within one event,
// face records name their vertices through a table of the event's first four vertices
// (its ids, then the vertices of its records as they come): a record whose three vertices
// are in the table is one byte. Slots and input indices are differences from the previous
// one. zstd compresses the result further. A block starts from a reset coder so that it
// decodes on its own.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "meshstep/replay/decoded_events.hpp"
#include "meshstep/replay/event.hpp"

namespace meshstep::replay::codec {

// Malformed encoded data; the reader adds where it was found.
class FormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The state both sides keep in step: the recent-vertex cache and the running references.
struct CoderState {
  static constexpr std::size_t kCache = 64;
  std::array<std::uint32_t, kCache> cache;
  std::uint32_t last_vertex = 0, slot_ref = 0, input_ref = 0;
  std::array<std::uint32_t, 4> table;  // the current event's first vertices
  std::size_t table_size = 0;
  CoderState() { cache.fill(kNone); }
  int find(std::uint32_t v) const {
    for (std::size_t i = 0; i < table_size; ++i)
      if (table[i] == v) return static_cast<int>(i);
    return -1;
  }
  void remember(std::uint32_t v) {
    if (v != kNone && table_size < table.size() && find(v) < 0) table[table_size++] = v;
  }
};

// The face writes of a flip, from its packed form (event_sink.hpp): the four faces before
// and after, paired by slot. Returns the number of writes (2 when the data structure reuses
// both slots, as Tds and Dcel do; up to 4).
std::size_t flip_writes(const std::array<std::uint32_t, 4>& abcd, const std::array<FaceId, 4>& slots,
                        std::uint32_t packed, SlotWrite out[4]);

// Writes through a raw pointer: the caller makes room for max_bytes(e) first (a block
// buffer grows once in a while instead of checking capacity at every byte).
class Encoder {
 public:
  void reset() { state_ = CoderState{}; }
  static std::size_t max_bytes(const Event& e);
  static constexpr std::size_t kMaxRecordBytes = 1 + 3 * 10;
  // Any event but a flip.
  std::uint8_t* event(const Event& e, std::uint8_t* out);
  // A flip, stored packed: its four vertices, the four slots and the rotation and
  // constraint bits that determine the records (flip_writes).
  std::uint8_t* flip(std::uint8_t code, const std::array<std::uint32_t, 4>& abcd,
                     const std::array<FaceId, 4>& slots, std::uint32_t packed, std::uint8_t* out);
  static constexpr std::size_t kMaxFlipBytes = 2 + 8 * 10 + 5;
  std::uint8_t* record(const FaceRecord& r, std::uint8_t* out);  // without the table

 private:
  std::uint8_t* vertex(std::uint32_t v, std::uint8_t* out);
  std::uint8_t* table_record(const FaceRecord& r, std::uint8_t* out);
  std::uint8_t* id(IdKind kind, std::uint32_t value, std::uint8_t* out);
  CoderState state_;
};

class Decoder {
 public:
  Decoder(const std::uint8_t* begin, const std::uint8_t* end) : p_(begin), begin_(begin), end_(end) {}
  bool done() const { return p_ == end_; }
  std::size_t offset() const { return static_cast<std::size_t>(p_ - begin_); }
  // Appends the next event to `out`. Throws FormatError.
  void event(DecodedEvents& out);
  FaceRecord record();  // without the table

 private:
  FaceRecord table_record();
  std::uint64_t varint();
  std::uint32_t u32(const char* what);
  std::uint32_t vertex();
  std::uint32_t id(IdKind kind);
  double f64();
  std::uint8_t byte(const char* what);
  const std::uint8_t* p_;
  const std::uint8_t* begin_;
  const std::uint8_t* end_;
  CoderState state_;
};

// Keyframes: the record of every slot, in slot order.
void encode_keyframe(std::span<const FaceRecord> slots, std::vector<std::uint8_t>& out);
std::vector<FaceRecord> decode_keyframe(std::span<const std::uint8_t> bytes, std::size_t count);

}  // namespace meshstep::replay::codec
