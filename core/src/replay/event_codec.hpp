// Events to bytes and back. The encoding is driven by each type's schema; ids are stored
// as varints, vertex ids and slots as differences from the previous one (neighbouring
// faces have neighbouring ids, so most differences fit in a byte), which zstd then
// compresses further. A block starts from reset coders so that it decodes on its own.
//
// Within one event, the faces of the mesh delta mostly reuse a few vertices (a flip's four,
// a split's new vertex and its ring): every vertex an event names goes into a small table,
// and a face record names its vertices by one-byte table positions; a vertex not yet in
// the table is written in full once (escape byte) and added.
#pragma once

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

class Encoder {
 public:
  void reset() { *this = Encoder{}; }
  void event(const Event& e, std::vector<std::uint8_t>& out);
  void record(const FaceRecord& r, std::vector<std::uint8_t>& out);

 private:
  void vertex(std::uint32_t v, std::vector<std::uint8_t>& out);
  void table_vertex(std::uint32_t v, std::vector<std::uint8_t>& out);
  void table_record(const FaceRecord& r, std::vector<std::uint8_t>& out);
  std::uint32_t table_[253];
  std::size_t table_size_ = 0;
  void id(IdKind kind, std::uint32_t value, std::vector<std::uint8_t>& out);
  std::uint32_t vertex_ref_ = 0, slot_ref_ = 0, input_ref_ = 0;
};

class Decoder {
 public:
  Decoder(const std::uint8_t* begin, const std::uint8_t* end) : p_(begin), begin_(begin), end_(end) {}
  bool done() const { return p_ == end_; }
  std::size_t offset() const { return static_cast<std::size_t>(p_ - begin_); }
  // Appends the next event to `out`. Throws FormatError.
  void event(DecodedEvents& out);
  FaceRecord record();

 private:
  std::uint32_t table_vertex();
  FaceRecord table_record();
  std::uint64_t varint();
  std::uint32_t u32(const char* what);
  std::uint32_t vertex();
  std::uint32_t id(IdKind kind);
  double f64();
  const std::uint8_t* p_;
  const std::uint8_t* begin_;
  const std::uint8_t* end_;
  std::uint32_t vertex_ref_ = 0, slot_ref_ = 0, input_ref_ = 0;
  std::uint32_t table_[253];
  std::size_t table_size_ = 0;
};

// Keyframes: the record of every slot, in slot order.
void encode_keyframe(std::span<const FaceRecord> slots, std::vector<std::uint8_t>& out);
std::vector<FaceRecord> decode_keyframe(std::span<const std::uint8_t> bytes, std::size_t count);

}  // namespace meshstep::replay::codec
