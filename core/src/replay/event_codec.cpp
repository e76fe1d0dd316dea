// Schema-driven event encoding (see event_codec.hpp).
#include "event_codec.hpp"

#include <bit>
#include <cstring>
#include <string>

#include "format.hpp"

namespace meshstep::replay::codec {
namespace {

using format::put_varint;
using format::unzigzag;
using format::zigzag;

constexpr std::uint8_t kDeadFlag = 0x80;
// Vertex references inside an event: a table position, or one of these.
constexpr std::uint8_t kTableCapacity = 253;
constexpr std::uint8_t kRefInfinite = 253;
constexpr std::uint8_t kRefNew = 254;

void put_f64(std::vector<std::uint8_t>& out, double d) { format::put_le(out, d); }

}  // namespace

// Vertex ids: 0 = kNone, 1 = kInfiniteVertex, else 2 + zigzag(difference from the previous).
void Encoder::vertex(std::uint32_t v, std::vector<std::uint8_t>& out) {
  if (v == kNone) {
    out.push_back(0);
  } else if (v == kInfiniteVertex) {
    out.push_back(1);
  } else {
    put_varint(out, 2 + zigzag(std::int64_t{v} - std::int64_t{vertex_ref_}));
    vertex_ref_ = v;
  }
}

void Encoder::id(IdKind kind, std::uint32_t value, std::vector<std::uint8_t>& out) {
  switch (kind) {
    case IdKind::vertex: vertex(value, out); return;
    case IdKind::count: put_varint(out, value); return;
    case IdKind::marker: put_varint(out, zigzag(static_cast<std::int32_t>(value))); return;
    case IdKind::slot:
    case IdKind::input: {
      std::uint32_t& ref = kind == IdKind::slot ? slot_ref_ : input_ref_;
      if (value == kNone) {
        out.push_back(0);
      } else {
        put_varint(out, 1 + zigzag(std::int64_t{value} - std::int64_t{ref}));
        ref = value;
      }
      return;
    }
  }
}

void Encoder::table_vertex(std::uint32_t v, std::vector<std::uint8_t>& out) {
  if (v == kInfiniteVertex) {
    out.push_back(kRefInfinite);
    return;
  }
  for (std::size_t i = 0; i < table_size_; ++i)
    if (table_[i] == v) {
      out.push_back(static_cast<std::uint8_t>(i));
      return;
    }
  out.push_back(kRefNew);
  vertex(v, out);
  if (table_size_ < kTableCapacity) table_[table_size_++] = v;
}

void Encoder::table_record(const FaceRecord& r, std::vector<std::uint8_t>& out) {
  if (r.dead()) {
    out.push_back(kDeadFlag);
    return;
  }
  out.push_back(r.constrained & 7);
  for (const VertexId v : r.v) table_vertex(v, out);
}

void Encoder::record(const FaceRecord& r, std::vector<std::uint8_t>& out) {
  if (r.dead()) {
    out.push_back(kDeadFlag);
    return;
  }
  out.push_back(r.constrained & 7);
  for (const VertexId v : r.v) vertex(v, out);
}

void Encoder::event(const Event& e, std::vector<std::uint8_t>& out) {
  const EventSchema& s = schema(e.type);
  out.push_back(static_cast<std::uint8_t>(e.type));
  out.push_back(e.code);
  table_size_ = 0;
  for (int i = 0; i < s.id_count; ++i) {
    id(s.id_kinds[i], e.ids[i], out);
    if (s.id_kinds[i] == IdKind::vertex && e.ids[i] < kInfiniteVertex) table_[table_size_++] = e.ids[i];
  }
  if (s.has_point) {
    put_f64(out, e.point.x);
    put_f64(out, e.point.y);
  }
  if (s.has_value) put_f64(out, e.value);
  if (s.has_list) {
    put_varint(out, e.list.size());
    for (const std::uint32_t x : e.list) vertex(x, out);
  }
  if (s.has_points) {
    put_varint(out, e.points.size());
    for (const Point& p : e.points) {
      put_f64(out, p.x);
      put_f64(out, p.y);
    }
  }
  if (s.has_writes) {
    put_varint(out, e.writes.size());
    for (const SlotWrite& w : e.writes) {
      id(IdKind::slot, w.slot, out);
      table_record(w.before, out);
      table_record(w.after, out);
    }
  }
}

std::uint64_t Decoder::varint() {
  std::uint64_t v = 0;
  for (int shift = 0; shift < 64; shift += 7) {
    if (p_ == end_) throw FormatError("event data ends in the middle of a number");
    const std::uint8_t b = *p_++;
    v |= std::uint64_t{b & 0x7Fu} << shift;
    if (!(b & 0x80)) return v;
  }
  throw FormatError("a number is longer than 64 bits");
}

std::uint32_t Decoder::u32(const char* what) {
  const std::uint64_t v = varint();
  if (v > 0xFFFFFFFFu) throw FormatError(std::string(what) + " out of range");
  return static_cast<std::uint32_t>(v);
}

std::uint32_t Decoder::vertex() {
  const std::uint64_t code = varint();
  if (code == 0) return kNone;
  if (code == 1) return kInfiniteVertex;
  const std::int64_t v = std::int64_t{vertex_ref_} + unzigzag(code - 2);
  if (v < 0 || v >= std::int64_t{kInfiniteVertex}) throw FormatError("vertex id out of range");
  vertex_ref_ = static_cast<std::uint32_t>(v);
  return vertex_ref_;
}

std::uint32_t Decoder::id(IdKind kind) {
  switch (kind) {
    case IdKind::vertex: return vertex();
    case IdKind::count: return u32("count");
    case IdKind::marker: {
      const std::int64_t m = unzigzag(varint());
      if (m < INT32_MIN || m > INT32_MAX) throw FormatError("segment marker out of range");
      return static_cast<std::uint32_t>(static_cast<std::int32_t>(m));
    }
    case IdKind::slot:
    case IdKind::input: {
      std::uint32_t& ref = kind == IdKind::slot ? slot_ref_ : input_ref_;
      const std::uint64_t code = varint();
      if (code == 0) return kNone;
      const std::int64_t v = std::int64_t{ref} + unzigzag(code - 1);
      if (v < 0 || v >= std::int64_t{kNone})
        throw FormatError(kind == IdKind::slot ? "face slot out of range" : "input index out of range");
      ref = static_cast<std::uint32_t>(v);
      return ref;
    }
  }
  throw FormatError("unknown id kind");
}

double Decoder::f64() {
  if (end_ - p_ < 8) throw FormatError("event data ends in the middle of a coordinate");
  double d;
  std::memcpy(&d, p_, 8);
  p_ += 8;
  return d;
}

std::uint32_t Decoder::table_vertex() {
  if (p_ == end_) throw FormatError("event data ends in the middle of a face record");
  const std::uint8_t ref = *p_++;
  if (ref == kRefInfinite) return kInfiniteVertex;
  if (ref == kRefNew) {
    const std::uint32_t v = vertex();
    if (v == kNone || v == kInfiniteVertex) throw FormatError("bad vertex in a face record");
    if (table_size_ < kTableCapacity) table_[table_size_++] = v;
    return v;
  }
  if (ref >= table_size_) throw FormatError("face record names a vertex the event does not have");
  return table_[ref];
}

FaceRecord Decoder::table_record() {
  if (p_ == end_) throw FormatError("event data ends in the middle of a face record");
  const std::uint8_t flags = *p_++;
  FaceRecord r;
  if (flags == kDeadFlag) return r;
  if (flags & ~7u) throw FormatError("bad face record flags");
  r.constrained = flags;
  for (VertexId& v : r.v) v = table_vertex();
  return r;
}

FaceRecord Decoder::record() {
  if (p_ == end_) throw FormatError("event data ends in the middle of a face record");
  const std::uint8_t flags = *p_++;
  FaceRecord r;
  if (flags == kDeadFlag) return r;
  if (flags & ~7u) throw FormatError("bad face record flags");
  r.constrained = flags;
  for (VertexId& v : r.v) {
    v = vertex();
    if (v == kNone) throw FormatError("a live face record names no vertex");
  }
  return r;
}

void Decoder::event(DecodedEvents& out) {
  if (end_ - p_ < 2) throw FormatError("event data ends in the middle of an event");
  const std::uint8_t type = *p_++;
  if (type >= kEventTypeCount)
    throw FormatError("unknown event type " + std::to_string(type) +
                      " (written by a newer meshstep?)");
  EventHead h{};
  h.type = static_cast<EventType>(type);
  h.code = *p_++;
  h.ids = {kNone, kNone, kNone, kNone};
  const EventSchema& s = schema(h.type);
  table_size_ = 0;
  for (int i = 0; i < s.id_count; ++i) {
    h.ids[i] = id(s.id_kinds[i]);
    if (s.id_kinds[i] == IdKind::vertex && h.ids[i] < kInfiniteVertex) table_[table_size_++] = h.ids[i];
  }
  if (s.has_point) h.point = {f64(), f64()};
  if (s.has_value) h.value = f64();
  // Counts are bounded by the bytes left (every element takes at least one byte), so a
  // corrupted count cannot make us allocate without bound.
  const auto count = [&](const char* what) {
    const std::uint64_t n = varint();
    if (n > static_cast<std::uint64_t>(end_ - p_)) throw FormatError(std::string(what) + " count too large");
    return static_cast<std::size_t>(n);
  };
  if (s.has_list) {
    const std::size_t n = count("list");
    for (std::size_t i = 0; i < n; ++i) out.lists.push_back(vertex());
  }
  if (s.has_points) {
    const std::size_t n = count("point");
    for (std::size_t i = 0; i < n; ++i) {
      const double x = f64();
      out.points.push_back({x, f64()});
    }
  }
  if (s.has_writes) {
    const std::size_t n = count("face write");
    for (std::size_t i = 0; i < n; ++i) {
      SlotWrite w;
      w.slot = id(IdKind::slot);
      if (w.slot == kNone) throw FormatError("face write without a slot");
      w.before = table_record();
      w.after = table_record();
      out.writes.push_back(w);
    }
  }
  h.list_end = static_cast<std::uint32_t>(out.lists.size());
  h.points_end = static_cast<std::uint32_t>(out.points.size());
  h.writes_end = static_cast<std::uint32_t>(out.writes.size());
  out.heads.push_back(h);
}

void encode_keyframe(std::span<const FaceRecord> slots, std::vector<std::uint8_t>& out) {
  Encoder e;
  for (const FaceRecord& r : slots) e.record(r, out);
}

std::vector<FaceRecord> decode_keyframe(std::span<const std::uint8_t> bytes, std::size_t count) {
  if (count > bytes.size()) throw FormatError("keyframe slot count larger than its data");
  Decoder d(bytes.data(), bytes.data() + bytes.size());
  std::vector<FaceRecord> slots(count);
  for (FaceRecord& r : slots) r = d.record();
  if (!d.done()) throw FormatError("keyframe has data after its last slot");
  return slots;
}

}  // namespace meshstep::replay::codec
