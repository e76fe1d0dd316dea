// Schema-driven event encoding (see event_codec.hpp).
#include "event_codec.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>
#include <string>

#include "format.hpp"
#include "meshstep/replay/mesh_hash.hpp"

namespace meshstep::replay::codec {
namespace {

using format::unzigzag;
using format::zigzag;

// Vertex codes: 0 none, 1 the vertex at infinity, 2 + slot for a hit in the recent-vertex
// cache, kFullVertex + zigzag(difference from the last vertex written in full) otherwise.
// Format 5 puts kFreshVertex (CoderState::vertex_top) before the full codes.
constexpr std::uint64_t kFreshVertex = 2 + CoderState::kCache;
constexpr std::uint64_t full_vertex_base(std::uint32_t version) {
  return version >= format::kCompactVersion ? kFreshVertex + 1 : kFreshVertex;
}
// Record headers: constraint bits 0..7 then three vertex codes; kDead; or kTableRecord |
// three 2-bit table positions, plus kTableFlags when a byte of constraint bits follows.
constexpr std::uint8_t kDead = 0x08;
constexpr std::uint8_t kTableRecord = 0x80;
constexpr std::uint8_t kTableFlags = 0x40;
// A walk's step codes (Encoder::walk): 3 * edge + rotation for a face across an edge of the
// one before, kWholeFace for one stored whole.
constexpr std::uint8_t kWholeFace = 0xF;

// Format 5's first byte of an event. Below kPackedHead: the type in the low 5 bits and the
// code in the next two (kCodeFollows: the code is the next byte). Above, the two packed
// events, whose code and layout the byte carries:
//   10rrrcmm  a flip: reason r; c: a varint of constraint bits follows the rotations; mm: its
//             slots after, 0: the same as before, 1: swapped, 2: written out
//   1100000g  a split_face; g: its bits follow whole (a varint) instead of a rotation byte
constexpr std::uint8_t kPackedHead = 0x80;
constexpr std::uint8_t kSplitFaceHead = 0xC0;
constexpr std::uint8_t kCodeFollows = 3;
static_assert(kEventTypeCount <= 32, "format 5 keeps an event's type in 5 bits");
// A split_face's spoke slots in format 5, two bits each in a byte: the slot split, a fresh
// slot (CoderState::slot_top), or written out.
enum SpokeSlot : std::uint8_t { kSplitSlot = 0, kFreshSlot = 1, kWrittenSlot = 2 };

std::uint8_t* put_varint(std::uint8_t* out, std::uint64_t v) {
  while (v >= 0x80) {
    *out++ = static_cast<std::uint8_t>(v | 0x80);
    v >>= 7;
  }
  *out++ = static_cast<std::uint8_t>(v);
  return out;
}

std::uint8_t* put_f64(std::uint8_t* out, double d) {
  std::memcpy(out, &d, 8);
  return out + 8;
}

}  // namespace

namespace {

// The record of a face whose vertices, counterclockwise, are `order`, listed by the data
// structure from order[rotation], with the given constraint bits.
FaceRecord rotated(const std::array<VertexId, 3>& order, std::uint32_t rotation, std::uint32_t flags) {
  FaceRecord r;
  r.v = {order[rotation % 3], order[(rotation + 1) % 3], order[(rotation + 2) % 3]};
  r.constrained = static_cast<std::uint8_t>(flags & 7);
  return r;
}

// Adds `after` as what `slot` holds after the change: on the write that emptied the slot if
// there is one, else as a write to a slot that was dead.
void pair_after(SlotWrite out[4], std::size_t& n, FaceId slot, const FaceRecord& after) {
  for (std::size_t i = 0; i < n; ++i)
    if (out[i].slot == slot && out[i].after.dead()) {
      out[i].after = after;
      return;
    }
  out[n++] = {slot, FaceRecord{}, after};
}

}  // namespace

std::size_t flip_writes(const std::array<std::uint32_t, 4>& abcd, const std::array<FaceId, 4>& slots,
                        std::uint32_t packed, SlotWrite out[4]) {
  const auto [a, b, c, d] = abcd;
  const auto face = [&](int i, VertexId x, VertexId y, VertexId z) {
    const std::uint32_t bits = packed >> (5 * i);
    return rotated({x, y, z}, bits & 3, bits >> 2);
  };
  out[0] = {slots[0], face(0, a, b, c), FaceRecord{}};
  out[1] = {slots[1], face(1, b, a, d), FaceRecord{}};
  std::size_t n = 2;
  pair_after(out, n, slots[2], face(2, c, d, b));
  pair_after(out, n, slots[3], face(3, d, c, a));
  return n;
}

std::size_t split_face_writes(VertexId v, const std::array<std::uint32_t, 3>& abc, FaceId slot,
                              const std::array<FaceId, 3>& spokes, std::uint32_t packed, SlotWrite out[4]) {
  out[0] = {slot, rotated(abc, 0, packed), FaceRecord{}};
  std::size_t n = 1;
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t bits = packed >> (3 + 7 * i);
    const std::uint32_t edge = bits & 3;
    pair_after(out, n, spokes[i], rotated({abc[edge], abc[(edge + 1) % 3], v}, (bits >> 2) & 3, bits >> 4));
  }
  return n;
}

// A list element takes up to 10 bytes, and a walk's face up to half a byte more (its step
// code), so 11 per element.
std::size_t Encoder::max_bytes(const Event& e) {
  return 2 + 4 * 10 + 16 + 8 + 10 + 11 * e.list.size() + 10 + 16 * e.points.size() + 10 +
         e.writes.size() * (10 + 2 * kMaxRecordBytes + 2);
}

std::uint8_t* Encoder::vertex(std::uint32_t v, std::uint8_t* out) {
  if (v == kNone) {
    *out++ = 0;
    return out;
  }
  if (v == kInfiniteVertex) {
    *out++ = 1;
    return out;
  }
  const std::size_t slot = v % CoderState::kCache;
  if (state_.cache[slot] == v) {
    *out++ = static_cast<std::uint8_t>(2 + slot);
    return out;
  }
  if (version_ >= format::kCompactVersion && v == state_.vertex_top) {
    *out++ = static_cast<std::uint8_t>(kFreshVertex);
  } else {
    out = put_varint(out, full_vertex_base(version_) + zigzag(std::int64_t{v} - std::int64_t{state_.last_vertex}));
  }
  state_.last_vertex = v;
  state_.cache[slot] = v;
  state_.vertex_top = std::max(state_.vertex_top, v + 1);
  return out;
}

std::uint8_t* Encoder::id(IdKind kind, std::uint32_t value, std::uint8_t* out) {
  switch (kind) {
    case IdKind::vertex:
      out = vertex(value, out);
      state_.remember(value);
      return out;
    case IdKind::count: return put_varint(out, value);
    case IdKind::marker: return put_varint(out, zigzag(static_cast<std::int32_t>(value)));
    case IdKind::slot:
    case IdKind::input: {
      std::uint32_t& ref = kind == IdKind::slot ? state_.slot_ref : state_.input_ref;
      if (value == kNone) {
        *out++ = 0;
        return out;
      }
      out = put_varint(out, 1 + zigzag(std::int64_t{value} - std::int64_t{ref}));
      ref = value;
      if (kind == IdKind::slot) state_.slot_top = std::max(state_.slot_top, value + 1);
      return out;
    }
  }
  return out;
}

std::uint8_t* Encoder::record(const FaceRecord& r, std::uint8_t* out) {
  if (r.dead()) {
    *out++ = kDead;
    return out;
  }
  *out++ = r.constrained & 7;
  for (const VertexId v : r.v) out = vertex(v, out);
  return out;
}

std::uint8_t* Encoder::table_record(const FaceRecord& r, std::uint8_t* out) {
  if (!r.dead()) {
    const int i0 = state_.find(r.v[0]), i1 = state_.find(r.v[1]), i2 = state_.find(r.v[2]);
    if (i0 >= 0 && i1 >= 0 && i2 >= 0) {
      const auto flags = static_cast<std::uint8_t>(r.constrained & 7);
      *out++ = static_cast<std::uint8_t>(kTableRecord | (flags ? kTableFlags : 0) | i0 | i1 << 2 | i2 << 4);
      if (flags) *out++ = flags;
      return out;
    }
  }
  out = record(r, out);
  if (!r.dead())
    for (const VertexId v : r.v) state_.remember(v);
  return out;
}

namespace {

// The step code of face g after face f (see Encoder::walk), and the position in g of its
// vertex opposite the edge it shares with f (-1 with kWholeFace).
std::uint8_t walk_step(const std::uint32_t* f, const std::uint32_t* g, int& fresh) {
  constexpr int kNext[3] = {1, 2, 0};
  for (int at = 0; at < 3; ++at) {
    // Is g[at] -> g[at + 1] the edge f[i + 1] -> f[i] of f, for some i?
    const std::uint32_t y = g[kNext[at]];
    const int i = f[0] == y ? 0 : f[1] == y ? 1 : f[2] == y ? 2 : -1;
    if (i >= 0 && f[kNext[i]] == g[at]) {
      fresh = kNext[kNext[at]];
      // g is listed from g[at] = f[i + 1], the first of (f[i + 1], f[i], w) when at is 0,
      // the third when at is 1 (g[0] is w), the second when at is 2.
      return static_cast<std::uint8_t>(3 * i + (3 - at) % 3);
    }
  }
  fresh = -1;
  return kWholeFace;
}

}  // namespace

// A locate event's walk: faces as vertex triples, each (as the recorder writes them) across
// an edge of the one before. Stored as the number of faces, the first face's vertices, then
// a step code per further face, two to a byte (low nibble first), and then per further face
// its vertex opposite the shared edge. Step code 3 * i + r: the face is across edge i of the
// face before, f[i] -> f[i + 1], so it holds f[i + 1], f[i] and its new vertex w in that
// order, listed from the r-th of them. A face that shares no edge with the one before (none
// does in a walk) has code kWholeFace and its three vertices in place of w.
std::uint8_t* Encoder::walk(std::span<const std::uint32_t> list, std::uint8_t* out) {
  if (list.size() % 3 != 0) throw std::logic_error("a locate event's walk is not a list of faces");
  const std::size_t faces = list.size() / 3;
  out = put_varint(out, faces);
  if (faces == 0) return out;
  for (int k = 0; k < 3; ++k) out = vertex(list[k], out);
  std::uint8_t* codes = out;
  out += faces / 2;  // (faces - 1) codes, two to a byte, rounded up
  for (std::size_t j = 0; j + 1 < faces; ++j) {
    const std::uint32_t* g = &list[3 * (j + 1)];
    int fresh;
    const std::uint8_t code = walk_step(&list[3 * j], g, fresh);
    codes[j / 2] = j % 2 ? static_cast<std::uint8_t>(codes[j / 2] | code << 4) : code;
    if (fresh >= 0) {
      out = vertex(g[fresh], out);
    } else {
      for (int k = 0; k < 3; ++k) out = vertex(g[k], out);
    }
  }
  return out;
}

// Flattened: the per-vertex helpers run a dozen times per event and GCC keeps them out of
// line otherwise.
[[gnu::flatten]] std::uint8_t* Encoder::event(const Event& e, std::uint8_t* out) {
  const EventSchema& s = schema(e.type);
  out = head(e.type, e.code, out);
  state_.table_size = 0;
  for (int i = 0; i < s.id_count; ++i) out = id(s.id_kinds[i], e.ids[i], out);
  if (s.has_point) {
    out = put_f64(out, e.point.x);
    out = put_f64(out, e.point.y);
  }
  if (s.has_value) out = put_f64(out, e.value);
  if (e.type == EventType::locate && stores_list(s, e.type, version_)) {
    out = walk(e.list, out);
  } else if (stores_list(s, e.type, version_)) {
    out = put_varint(out, e.list.size());
    for (const std::uint32_t x : e.list) out = vertex(x, out);
  }
  if (s.has_points) {
    out = put_varint(out, e.points.size());
    for (const Point& p : e.points) {
      out = put_f64(out, p.x);
      out = put_f64(out, p.y);
    }
  }
  if (s.has_writes) {
    out = put_varint(out, e.writes.size());
    for (const SlotWrite& w : e.writes) {
      out = id(IdKind::slot, w.slot, out);
      out = table_record(w.before, out);
      out = table_record(w.after, out);
    }
  }
  return out;
}

std::uint8_t* Encoder::head(EventType type, std::uint8_t code, std::uint8_t* out) {
  if (version_ < format::kCompactVersion) {
    *out++ = static_cast<std::uint8_t>(type);
    *out++ = code;
    return out;
  }
  const std::uint8_t inline_code = code < kCodeFollows ? code : kCodeFollows;
  *out++ = static_cast<std::uint8_t>(static_cast<std::uint8_t>(type) | inline_code << 5);
  if (inline_code == kCodeFollows) *out++ = code;
  return out;
}

// Format 5's flip: the data structures reuse both slots (the faces after are the faces
// before, in the same or the swapped order), and rotations fill a byte (a Delaunay run has
// no constraint bits).
std::uint8_t* Encoder::compact_flip(std::uint8_t code, const std::array<std::uint32_t, 4>& abcd,
                                    const std::array<FaceId, 4>& slots, std::uint32_t packed, std::uint8_t* out) {
  std::uint32_t rotations = 0, constraints = 0;
  for (int i = 0; i < 4; ++i) {
    rotations |= ((packed >> (5 * i)) & 3u) << (2 * i);
    constraints |= ((packed >> (5 * i + 2)) & 7u) << (3 * i);
  }
  const std::uint8_t mode = slots[2] == slots[0] && slots[3] == slots[1]   ? 0
                            : slots[2] == slots[1] && slots[3] == slots[0] ? 1
                                                                           : 2;
  *out++ = static_cast<std::uint8_t>(kPackedHead | code << 3 | (constraints ? 4 : 0) | mode);
  for (const std::uint32_t v : abcd) out = vertex(v, out);
  out = id(IdKind::slot, slots[0], out);
  out = id(IdKind::slot, slots[1], out);
  if (mode == 2) {
    out = id(IdKind::slot, slots[2], out);
    out = id(IdKind::slot, slots[3], out);
  }
  *out++ = static_cast<std::uint8_t>(rotations);
  if (constraints) out = put_varint(out, constraints);
  return out;
}

[[gnu::flatten]] std::uint8_t* Encoder::flip(std::uint8_t code, const std::array<std::uint32_t, 4>& abcd,
                            const std::array<FaceId, 4>& slots, std::uint32_t packed, std::uint8_t* out) {
  if (version_ >= format::kCompactVersion && code < 8) return compact_flip(code, abcd, slots, packed, out);
  out = head(EventType::flip, code, out);
  for (const std::uint32_t v : abcd) out = vertex(v, out);
  for (const FaceId f : slots) out = id(IdKind::slot, f, out);
  return put_varint(out, packed);
}

[[gnu::flatten]] std::uint8_t* Encoder::split_face(VertexId v, const std::array<std::uint32_t, 3>& abc, FaceId slot,
                                  const std::array<FaceId, 3>& spokes, std::uint32_t packed,
                                  std::uint8_t* out) {
  if (version_ >= format::kCompactVersion) return compact_split_face(v, abc, slot, spokes, packed, out);
  *out++ = static_cast<std::uint8_t>(EventType::split_face);
  *out++ = 0;
  out = vertex(v, out);
  for (const std::uint32_t x : abc) out = vertex(x, out);
  out = id(IdKind::slot, slot, out);
  for (const FaceId f : spokes) out = id(IdKind::slot, f, out);
  return put_varint(out, packed);
}

// Format 5's split_face: of the three faces around the new vertex, one usually takes the
// split face's slot and the others fresh slots; each spoke i usually stands on the old
// face's edge i, without constraint bits, so three rotations fill a byte.
std::uint8_t* Encoder::compact_split_face(VertexId v, const std::array<std::uint32_t, 3>& abc, FaceId slot,
                                          const std::array<FaceId, 3>& spokes, std::uint32_t packed,
                                          std::uint8_t* out) {
  std::uint32_t rotations = 0;
  bool plain = (packed & 7u) == 0;
  for (std::uint32_t i = 0; i < 3; ++i) {
    const std::uint32_t bits = packed >> (3 + 7 * i);
    plain = plain && (bits & 3u) == i && ((bits >> 4) & 7u) == 0;
    rotations |= ((bits >> 2) & 3u) << (2 * i);
  }
  *out++ = static_cast<std::uint8_t>(kSplitFaceHead | (plain ? 0 : 1));
  out = vertex(v, out);
  for (const std::uint32_t x : abc) out = vertex(x, out);
  out = id(IdKind::slot, slot, out);
  std::uint8_t* modes = out++;
  *modes = 0;
  for (int i = 0; i < 3; ++i) {
    SpokeSlot mode = kWrittenSlot;
    if (spokes[i] == slot) {
      mode = kSplitSlot;
    } else if (spokes[i] == state_.slot_top) {
      mode = kFreshSlot;
      state_.slot_ref = spokes[i];
      state_.slot_top = spokes[i] + 1;
    } else {
      out = id(IdKind::slot, spokes[i], out);
    }
    *modes = static_cast<std::uint8_t>(*modes | mode << (2 * i));
  }
  if (plain) {
    *out++ = static_cast<std::uint8_t>(rotations);
    return out;
  }
  return put_varint(out, packed);
}

std::uint8_t Decoder::byte(const char* what) {
  if (p_ == end_) throw FormatError(std::string("event data ends in the middle of ") + what);
  return *p_++;
}

std::uint64_t Decoder::varint() {
  std::uint64_t v = 0;
  for (int shift = 0; shift < 64; shift += 7) {
    const std::uint8_t b = byte("a number");
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

namespace {

// base + the zigzag-coded difference, which must land in [0, limit). The difference is
// checked before it is added: a damaged log's can be anything up to 2^63.
std::uint32_t offset_id(std::uint32_t base, std::uint64_t zigzag_code, std::uint32_t limit, const char* what) {
  const std::int64_t delta = unzigzag(zigzag_code);
  if (delta < -std::int64_t{base} || delta >= std::int64_t{limit} - std::int64_t{base}) throw FormatError(what);
  return static_cast<std::uint32_t>(std::int64_t{base} + delta);
}

}  // namespace

std::uint32_t Decoder::vertex() {
  const std::uint64_t code = varint();
  if (code == 0) return kNone;
  if (code == 1) return kInfiniteVertex;
  if (code < kFreshVertex) {
    const std::uint32_t v = state_.cache[code - 2];
    if (v == kNone) throw FormatError("vertex refers to an empty cache slot");
    return v;
  }
  const std::uint64_t full = full_vertex_base(version_);
  if (code < full) {  // kFreshVertex, format 5
    if (state_.vertex_top >= kInfiniteVertex) throw FormatError("vertex id out of range");
    state_.last_vertex = state_.vertex_top;
  } else {
    state_.last_vertex = offset_id(state_.last_vertex, code - full, kInfiniteVertex, "vertex id out of range");
  }
  state_.cache[state_.last_vertex % CoderState::kCache] = state_.last_vertex;
  state_.vertex_top = std::max(state_.vertex_top, state_.last_vertex + 1);
  return state_.last_vertex;
}

std::uint32_t Decoder::id(IdKind kind) {
  switch (kind) {
    case IdKind::vertex: {
      const std::uint32_t v = vertex();
      state_.remember(v);
      return v;
    }
    case IdKind::count: return u32("count");
    case IdKind::marker: {
      const std::int64_t m = unzigzag(varint());
      if (m < INT32_MIN || m > INT32_MAX) throw FormatError("segment marker out of range");
      return static_cast<std::uint32_t>(static_cast<std::int32_t>(m));
    }
    case IdKind::slot:
    case IdKind::input: {
      std::uint32_t& ref = kind == IdKind::slot ? state_.slot_ref : state_.input_ref;
      const std::uint64_t code = varint();
      if (code == 0) return kNone;
      ref = offset_id(ref, code - 1, kNone, kind == IdKind::slot ? "face slot out of range" : "input index out of range");
      if (kind == IdKind::slot) state_.slot_top = std::max(state_.slot_top, ref + 1);
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

FaceRecord Decoder::record() {
  const std::uint8_t flags = byte("a face record");
  FaceRecord r;
  if (flags == kDead) return r;
  if (flags > 7) throw FormatError("bad face record header");
  r.constrained = flags;
  for (VertexId& v : r.v) {
    v = vertex();
    if (v == kNone) throw FormatError("a live face record names no vertex");
  }
  return r;
}

FaceRecord Decoder::table_record() {
  if (p_ == end_ || !(*p_ & kTableRecord)) {  // record() reads the header itself
    const FaceRecord r = record();
    if (!r.dead())
      for (const VertexId v : r.v) state_.remember(v);
    return r;
  }
  const std::uint8_t head = *p_++;
  FaceRecord r;
  for (int i = 0; i < 3; ++i) {
    const std::size_t at = (head >> (2 * i)) & 3u;
    if (at >= state_.table_size) throw FormatError("face record names a vertex the event does not have");
    r.v[i] = state_.table[at];
  }
  if (head & kTableFlags) {
    r.constrained = byte("a face record");
    if (r.constrained == 0 || r.constrained > 7) throw FormatError("bad face record flags");
  }
  return r;
}

void Decoder::event(DecodedEvents& out) {
  std::uint8_t type, code;
  if (version_ >= format::kCompactVersion) {
    const std::uint8_t first = byte("an event");
    if (first >= kSplitFaceHead) return compact_split_face(first, out);
    if (first >= kPackedHead) return compact_flip(first, out);
    type = first & 0x1F;
    code = static_cast<std::uint8_t>(first >> 5);
    if (code == kCodeFollows) code = byte("an event");
  } else {
    if (end_ - p_ < 2) throw FormatError("event data ends in the middle of an event");
    type = *p_++;
    code = *p_++;
  }
  if (type >= format::event_type_count(version_))
    throw FormatError("unknown event type " + std::to_string(type) + " (written by a newer meshstep?)");
  EventHead h{};
  h.type = static_cast<EventType>(type);
  h.code = code;
  h.ids = {kNone, kNone, kNone, kNone};
  if (h.type == EventType::flip) return flip(h, out);
  if (h.type == EventType::split_face) return split_face(h, out);
  const EventSchema& s = schema(h.type);
  state_.table_size = 0;
  for (int i = 0; i < s.id_count; ++i) h.ids[i] = id(s.id_kinds[i]);
  if (s.has_point) {
    const double x = f64();
    h.point = {x, f64()};
  }
  if (s.has_value) h.value = f64();
  // Counts are bounded by the bytes left (every element takes at least one byte), so a
  // corrupted count cannot make us allocate without bound.
  const auto count = [&](const char* what) {
    const std::uint64_t n = varint();
    if (n > static_cast<std::uint64_t>(end_ - p_)) throw FormatError(std::string(what) + " count too large");
    return static_cast<std::size_t>(n);
  };
  if (h.type == EventType::locate && stores_list(s, h.type, version_)) {
    walk(out);
  } else if (stores_list(s, h.type, version_)) {
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
  push(h, out);
}

// See Encoder::walk.
void Decoder::walk(DecodedEvents& out) {
  const std::uint64_t faces = varint();
  // A face past the first takes a nibble and a byte at least: the count is bounded by the
  // bytes left, so a corrupted one cannot make us allocate without bound.
  if (faces > 1 + static_cast<std::uint64_t>(end_ - p_)) throw FormatError("walk face count too large");
  if (faces == 0) return;
  const std::size_t code_bytes = static_cast<std::size_t>(faces / 2);
  std::array<std::uint32_t, 3> f;
  for (std::uint32_t& v : f) v = vertex();
  out.lists.insert(out.lists.end(), f.begin(), f.end());
  if (static_cast<std::size_t>(end_ - p_) < code_bytes) throw FormatError("event data ends in the middle of a walk");
  const std::uint8_t* codes = p_;
  p_ += code_bytes;
  for (std::size_t j = 0; j + 1 < faces; ++j) {
    const std::uint8_t code = (codes[j / 2] >> (4 * (j % 2))) & 0xF;
    std::array<std::uint32_t, 3> g;
    if (code == kWholeFace) {
      for (std::uint32_t& v : g) v = vertex();
    } else {
      if (code >= 9) throw FormatError("bad walk step");
      const int i = code / 3, r = code % 3;
      const std::array<std::uint32_t, 3> across{f[(i + 1) % 3], f[i], vertex()};
      g = {across[r], across[(r + 1) % 3], across[(r + 2) % 3]};
    }
    out.lists.insert(out.lists.end(), g.begin(), g.end());
    f = g;
  }
}

void Decoder::push(EventHead& h, DecodedEvents& out) {
  h.list_end = static_cast<std::uint32_t>(out.lists.size());
  h.points_end = static_cast<std::uint32_t>(out.points.size());
  h.writes_end = static_cast<std::uint32_t>(out.writes.size());
  out.heads.push_back(h);
}

void Decoder::flip(EventHead& h, DecodedEvents& out) {
  std::array<std::uint32_t, 4> abcd;
  for (std::uint32_t& v : abcd) {
    v = vertex();
    if (v == kNone) throw FormatError("a flip names no vertex");
  }
  std::array<FaceId, 4> slots;
  for (FaceId& f : slots) {
    f = id(IdKind::slot);
    if (f == kNone) throw FormatError("a flip names no face slot");
  }
  const std::uint64_t packed = varint();
  if (packed >= (1u << 20)) throw FormatError("bad flip bits");
  for (int i = 0; i < 4; ++i)
    if (((packed >> (5 * i)) & 3u) == 3u) throw FormatError("bad flip rotation");
  SlotWrite writes[4];
  const std::size_t n = flip_writes(abcd, slots, static_cast<std::uint32_t>(packed), writes);
  out.writes.insert(out.writes.end(), writes, writes + n);
  std::copy(abcd.begin(), abcd.end(), h.ids.begin());
  push(h, out);
}

void Decoder::split_face(EventHead& h, DecodedEvents& out) {
  const VertexId v = vertex();
  std::array<std::uint32_t, 3> abc;
  for (std::uint32_t& x : abc) x = vertex();
  if (v == kNone || abc[0] == kNone || abc[1] == kNone || abc[2] == kNone)
    throw FormatError("a split_face names no vertex");
  const FaceId slot = id(IdKind::slot);
  std::array<FaceId, 3> spokes;
  for (FaceId& f : spokes) f = id(IdKind::slot);
  if (slot == kNone || spokes[0] == kNone || spokes[1] == kNone || spokes[2] == kNone)
    throw FormatError("a split_face names no face slot");
  const std::uint64_t packed = varint();
  if (packed >= (1u << 24)) throw FormatError("bad split_face bits");
  for (int i = 0; i < 3; ++i) {
    const std::uint64_t bits = packed >> (3 + 7 * i);
    if ((bits & 3u) == 3u || ((bits >> 2) & 3u) == 3u) throw FormatError("bad split_face edge or rotation");
  }
  SlotWrite writes[4];
  const std::size_t n = split_face_writes(v, abc, slot, spokes, static_cast<std::uint32_t>(packed), writes);
  out.writes.insert(out.writes.end(), writes, writes + n);
  h.ids[0] = v;
  push(h, out);
}

void Decoder::compact_flip(std::uint8_t first, DecodedEvents& out) {
  EventHead h{};
  h.type = EventType::flip;
  h.code = static_cast<std::uint8_t>((first >> 3) & 7u);
  const std::uint32_t mode = first & 3u;
  if (mode == 3) throw FormatError("bad flip slots");
  std::array<std::uint32_t, 4> abcd;
  for (std::uint32_t& v : abcd) {
    v = vertex();
    if (v == kNone) throw FormatError("a flip names no vertex");
  }
  std::array<FaceId, 4> slots;
  const int written = mode == 2 ? 4 : 2;
  for (int i = 0; i < written; ++i) {
    slots[i] = id(IdKind::slot);
    if (slots[i] == kNone) throw FormatError("a flip names no face slot");
  }
  if (mode == 0) slots[2] = slots[0], slots[3] = slots[1];
  if (mode == 1) slots[2] = slots[1], slots[3] = slots[0];
  const std::uint8_t rotations = byte("a flip");
  const std::uint64_t constraints = (first & 4u) ? varint() : 0;
  if (constraints >= (1u << 12)) throw FormatError("bad flip bits");
  std::uint32_t packed = 0;
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t rotation = (rotations >> (2 * i)) & 3u;
    if (rotation == 3u) throw FormatError("bad flip rotation");
    packed |= (rotation | static_cast<std::uint32_t>((constraints >> (3 * i)) & 7u) << 2) << (5 * i);
  }
  SlotWrite writes[4];
  const std::size_t n = flip_writes(abcd, slots, packed, writes);
  out.writes.insert(out.writes.end(), writes, writes + n);
  h.ids = {abcd[0], abcd[1], abcd[2], abcd[3]};
  push(h, out);
}

// The slot after the largest written (Encoder::compact_split_face).
FaceId Decoder::fresh_slot() {
  if (state_.slot_top >= kNone) throw FormatError("face slot out of range");
  state_.slot_ref = state_.slot_top++;
  return state_.slot_ref;
}

void Decoder::compact_split_face(std::uint8_t first, DecodedEvents& out) {
  if (first > (kSplitFaceHead | 1)) throw FormatError("unknown event head " + std::to_string(first));
  EventHead h{};
  h.type = EventType::split_face;
  h.ids = {kNone, kNone, kNone, kNone};
  const VertexId v = vertex();
  std::array<std::uint32_t, 3> abc;
  for (std::uint32_t& x : abc) x = vertex();
  if (v == kNone || abc[0] == kNone || abc[1] == kNone || abc[2] == kNone)
    throw FormatError("a split_face names no vertex");
  const FaceId slot = id(IdKind::slot);
  if (slot == kNone) throw FormatError("a split_face names no face slot");
  const std::uint8_t modes = byte("a split_face");
  std::array<FaceId, 3> spokes;
  for (int i = 0; i < 3; ++i) {
    switch ((modes >> (2 * i)) & 3u) {
      case kSplitSlot: spokes[i] = slot; break;
      case kFreshSlot: spokes[i] = fresh_slot(); break;
      case kWrittenSlot:
        spokes[i] = id(IdKind::slot);
        if (spokes[i] == kNone) throw FormatError("a split_face names no face slot");
        break;
      default: throw FormatError("bad split_face slots");
    }
  }
  std::uint64_t packed = 0;
  if (first & 1u) {
    packed = varint();
    if (packed >= (1u << 24)) throw FormatError("bad split_face bits");
  } else {
    const std::uint8_t rotations = byte("a split_face");
    for (std::uint32_t i = 0; i < 3; ++i) packed |= std::uint64_t{i | ((rotations >> (2 * i)) & 3u) << 2} << (3 + 7 * i);
  }
  for (int i = 0; i < 3; ++i) {
    const std::uint64_t bits = packed >> (3 + 7 * i);
    if ((bits & 3u) == 3u || ((bits >> 2) & 3u) == 3u) throw FormatError("bad split_face edge or rotation");
  }
  SlotWrite writes[4];
  const std::size_t n = split_face_writes(v, abc, slot, spokes, static_cast<std::uint32_t>(packed), writes);
  out.writes.insert(out.writes.end(), writes, writes + n);
  h.ids[0] = v;
  push(h, out);
}

namespace {

std::uint32_t zigzag32(std::uint32_t d) {
  return (d << 1) ^ static_cast<std::uint32_t>(static_cast<std::int32_t>(d) >> 31);
}
std::uint32_t unzigzag32(std::uint32_t z) { return (z >> 1) ^ (0u - (z & 1u)); }
unsigned byte_length(std::uint32_t x) { return (static_cast<unsigned>(std::bit_width(x | 1u)) + 7) / 8; }

constexpr std::uint8_t kDeadSlot = 0x80;
constexpr std::uint8_t kSlotFlags = 0x40;

}  // namespace

std::uint8_t* KeyframeEncoder::slots(const std::uint32_t* words, std::size_t count, std::uint8_t* out,
                                     std::uint64_t& hash) {
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < count; ++i, words += 4) {
    FaceRecord r;
    r.v = {words[0], words[1], words[2]};
    r.constrained = static_cast<std::uint8_t>(words[3] & 7);
    sum += face_hash(r);
    if (r.dead()) {
      *out++ = kDeadSlot;
      continue;
    }
    const std::uint32_t d[3] = {zigzag32(r.v[0] - previous_), zigzag32(r.v[1] - r.v[0]), zigzag32(r.v[2] - r.v[0])};
    previous_ = r.v[0];
    const unsigned n0 = byte_length(d[0]), n1 = byte_length(d[1]), n2 = byte_length(d[2]);
    *out++ = static_cast<std::uint8_t>((n0 - 1) | (n1 - 1) << 2 | (n2 - 1) << 4 | (r.constrained ? kSlotFlags : 0));
    std::memcpy(out, &d[0], 4);  // little-endian hosts (format.hpp checks)
    out += n0;
    std::memcpy(out, &d[1], 4);
    out += n1;
    std::memcpy(out, &d[2], 4);
    out += n2;
    *out = r.constrained;
    out += r.constrained != 0;
  }
  hash += sum;
  return out;
}

std::vector<FaceRecord> decode_keyframe(std::span<const std::uint8_t> bytes, std::size_t count) {
  if (count > bytes.size()) throw FormatError("keyframe slot count larger than its data");
  std::vector<FaceRecord> slots(count);
  const std::uint8_t* p = bytes.data();
  const std::uint8_t* const end = p + bytes.size();
  std::uint32_t previous = 0;
  for (FaceRecord& r : slots) {
    if (p == end) throw FormatError("keyframe data ends before its last slot");
    const std::uint8_t control = *p++;
    if (control == kDeadSlot) continue;
    if (control & kDeadSlot) throw FormatError("bad keyframe slot header");
    const unsigned n[3] = {(control & 3u) + 1, ((control >> 2) & 3u) + 1, ((control >> 4) & 3u) + 1};
    if (static_cast<std::size_t>(end - p) < n[0] + n[1] + n[2] + ((control & kSlotFlags) ? 1 : 0))
      throw FormatError("keyframe data ends in the middle of a slot");
    std::uint32_t d[3];
    for (int i = 0; i < 3; ++i) {
      d[i] = 0;
      for (unsigned b = 0; b < n[i]; ++b) d[i] |= std::uint32_t{*p++} << (8 * b);
    }
    r.v[0] = previous + unzigzag32(d[0]);
    r.v[1] = r.v[0] + unzigzag32(d[1]);
    r.v[2] = r.v[0] + unzigzag32(d[2]);
    previous = r.v[0];
    if (r.v[0] == kNone || r.v[1] == kNone || r.v[2] == kNone)
      throw FormatError("a live keyframe slot names no vertex");
    if (control & kSlotFlags) {
      r.constrained = *p++;
      if (r.constrained == 0 || r.constrained > 7) throw FormatError("bad keyframe constraint bits");
    }
  }
  if (p != end) throw FormatError("keyframe has data after its last slot");
  return slots;
}

}  // namespace meshstep::replay::codec
