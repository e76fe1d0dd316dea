// Events to bytes and back, driven by each type's schema.
//
// Vertex ids dominate the data, and most of them repeat ones just written: a flip names
// the vertex being inserted and the edge the previous change made. So a vertex is written
// as one byte when it is in a small direct-mapped cache of recent vertices (slot v % 64),
// and otherwise as the difference from the last vertex written in full. Within one event,
// face records name their vertices through a table of the event's first four vertices
// (its ids, then the vertices of its records as they come): a record whose three vertices
// are in the table is one byte. Slots and input indices are differences from the previous
// one. A locate event's walk is a chain of faces each sharing an edge with the one before,
// so past its first face a face is stored as the edge it shares, its rotation and its one
// other vertex (Encoder::walk). zstd compresses the result further. A block starts from a
// reset coder so that it decodes on its own.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "format.hpp"
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
  // Format 5: one past the largest vertex and slot written since the block began, which is
  // what a run names next when it makes a vertex or a face (a fresh vertex, a fresh slot).
  std::uint32_t vertex_top = 0, slot_top = 0;
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

// Whether events of this type store their list in a file of format `version` (locate events
// carry their walk from version 3 on).
inline bool stores_list(const EventSchema& s, EventType type, std::uint32_t version) {
  return s.has_list && (type != EventType::locate || version >= format::kLocateWalkVersion);
}

// The face writes of a flip, from its packed form (event_sink.hpp): the four faces before
// and after, paired by slot. Returns the number of writes (2 when the data structure reuses
// both slots, as Tds and Dcel do; up to 4).
std::size_t flip_writes(const std::array<std::uint32_t, 4>& abcd, const std::array<FaceId, 4>& slots,
                        std::uint32_t packed, SlotWrite out[4]);

// The face writes of a split_face, from its packed form (event_sink.hpp): the face split
// and the three around the new vertex, paired by slot. Returns the number of writes.
std::size_t split_face_writes(VertexId v, const std::array<std::uint32_t, 3>& abc, FaceId slot,
                              const std::array<FaceId, 3>& spokes, std::uint32_t packed, SlotWrite out[4]);

// Writes through a raw pointer: the caller makes room for max_bytes(e) first (a block
// buffer grows once in a while instead of checking capacity at every byte).
class Encoder {
 public:
  // Writes events as files of format `version` store them (format.hpp).
  explicit Encoder(std::uint32_t version = format::kFormatVersion) : version_(version) {}
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
  // A split_face, stored packed likewise: v, the face split, its slot, the three new slots
  // and the bits of split_face_writes.
  std::uint8_t* split_face(VertexId v, const std::array<std::uint32_t, 3>& abc, FaceId slot,
                           const std::array<FaceId, 3>& spokes, std::uint32_t packed, std::uint8_t* out);
  static constexpr std::size_t kMaxSplitFaceBytes = 2 + 8 * 10 + 5;
  std::uint8_t* record(const FaceRecord& r, std::uint8_t* out);  // without the table

 private:
  std::uint8_t* head(EventType type, std::uint8_t code, std::uint8_t* out);
  std::uint8_t* compact_flip(std::uint8_t code, const std::array<std::uint32_t, 4>& abcd,
                             const std::array<FaceId, 4>& slots, std::uint32_t packed, std::uint8_t* out);
  std::uint8_t* compact_split_face(VertexId v, const std::array<std::uint32_t, 3>& abc, FaceId slot,
                                   const std::array<FaceId, 3>& spokes, std::uint32_t packed, std::uint8_t* out);
  std::uint8_t* vertex(std::uint32_t v, std::uint8_t* out);
  std::uint8_t* table_record(const FaceRecord& r, std::uint8_t* out);
  std::uint8_t* walk(std::span<const std::uint32_t> list, std::uint8_t* out);
  std::uint8_t* id(IdKind kind, std::uint32_t value, std::uint8_t* out);
  CoderState state_;
  std::uint32_t version_;
};

class Decoder {
 public:
  // Reads events of a file of format `version`.
  Decoder(const std::uint8_t* begin, const std::uint8_t* end, std::uint32_t version)
      : p_(begin), begin_(begin), end_(end), version_(version) {}
  bool done() const { return p_ == end_; }
  std::size_t offset() const { return static_cast<std::size_t>(p_ - begin_); }
  // Appends the next event to `out`. Throws FormatError.
  void event(DecodedEvents& out);
  FaceRecord record();  // without the table

 private:
  FaceRecord table_record();
  void walk(DecodedEvents& out);
  void flip(EventHead& h, DecodedEvents& out);
  void split_face(EventHead& h, DecodedEvents& out);
  void compact_flip(std::uint8_t first, DecodedEvents& out);
  void compact_split_face(std::uint8_t first, DecodedEvents& out);
  FaceId fresh_slot();
  void push(EventHead& h, DecodedEvents& out);
  std::uint64_t varint();
  std::uint32_t u32(const char* what);
  std::uint32_t vertex();
  std::uint32_t id(IdKind kind);
  double f64();
  std::uint8_t byte(const char* what);
  const std::uint8_t* p_;
  const std::uint8_t* begin_;
  const std::uint8_t* end_;
  std::uint32_t version_;
  CoderState state_;
};

// Keyframes: every slot, in slot order, in a layout of their own. A keyframe is a million
// records written in one go at the end of a run, so its encoding is branch-free rather than
// as small as the events': per slot a control byte (bit 7: dead, and nothing follows; bits
// 0-5: the byte lengths, less one, of three numbers; bit 6: a byte of constraint bits ends
// the slot), then, little-endian in those lengths, zigzag(v0 - v0 of the previous live
// slot), zigzag(v1 - v0) and zigzag(v2 - v0), differences taken modulo 2^32.
class KeyframeEncoder {
 public:
  // Bytes one slot may take, with the 3 that the last 4-byte store may write beyond it.
  static constexpr std::size_t kMaxSlotBytes = 1 + 3 * 4 + 1 + 3;
  // Encodes `count` slots from their raw words (v0, v1, v2, constraint bits each;
  // event_sink.hpp) and adds their face hashes (mesh_hash.hpp) to `hash`.
  std::uint8_t* slots(const std::uint32_t* words, std::size_t count, std::uint8_t* out, std::uint64_t& hash);

 private:
  std::uint32_t previous_ = 0;
};
std::vector<FaceRecord> decode_keyframe(std::span<const std::uint8_t> bytes, std::size_t count);

}  // namespace meshstep::replay::codec
