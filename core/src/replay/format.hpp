// The replay log's file format: constants, the block header, and the small binary helpers
// shared by the writer and the reader. Integers are little-endian.
//
//   file    := file_header block*
//   file_header := "MSTEPLOG" u32:format_version u32:L  fields[L bytes]  u64:checksum
//              fields := (u16 key length, key, u32 value length, value)*   (UTF-8 strings)
//   block   := block_header payload
//   block_header (56 bytes):
//     u32 magic "MSBK"   u8 kind   u8[3] zero   u32 stored_size   u32 raw_size
//     u64 first_event    u64 count   u64 mesh_hash   u32 steps   u32 header_check
//     u64 checksum
//   header_check: 32 bits of the checksum of the first 44 bytes, so that a damaged size is
//   reported as damage, not as a file that ends early
//   kind events:   payload = zstd(encoded events), count = number of events, first_event =
//                  index of the first, mesh_hash = 0, steps = number of step_begin events
//   kind keyframe: payload = face records of every slot, count = number of slots,
//                  first_event = number of events applied, mesh_hash = hash of that mesh;
//                  read from the algorithm's data structure (not rebuilt from events), the
//                  last one at the end of the run
//   kind end:      payload = zstd(summary: u64 events, u64 steps, u64 per event type),
//                  mesh_hash = the final keyframe's; written when the run finished; a
//                  file without it is truncated
//   checksum: of the header's first 48 bytes and the stored payload.
//   A payload is a zstd frame, or the bytes themselves when stored_size == raw_size (a zstd
//   frame is never exactly its content's size): keyframes, which do not compress, are
//   stored so.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "meshstep/replay/event.hpp"

namespace meshstep::replay::format {

static_assert(std::endian::native == std::endian::little,
              "the log format is little-endian and is read and written with memcpy");

inline constexpr char kFileMagic[8] = {'M', 'S', 'T', 'E', 'P', 'L', 'O', 'G'};
// 2: split_face events packed like flips; keyframes in a layout of their own.
// 3: locate events carry the faces of their walk (a list).
// 4: terrains: elevation events, the vertical_error criterion, point_selected's sample choices.
// 5: an event's type and code in one byte; flips and split_faces in a compact form (their
//    slots named by their relation to slots just written, rotations in a byte).
// 6: the header may name a recipe's operations (field `operations`, one per line), which map
//    the run's phases to its operations; events are encoded as in 5.
inline constexpr std::uint32_t kFormatVersion = 6;
// The oldest version read: a version-2 log reads as one whose locate events have no list.
inline constexpr std::uint32_t kOldestReadableVersion = 2;
inline constexpr std::uint32_t kLocateWalkVersion = 3;  // the first whose locate events have one
inline constexpr std::uint32_t kCompactVersion = 5;     // the first with compact event heads
inline constexpr std::uint32_t kOperationsVersion = 6;  // the first whose header names operations
// The event types a file of format `version` can hold (its end block counts each): every
// type before `elevation` until version 3.
inline constexpr std::size_t event_type_count(std::uint32_t version) {
  return version >= 4 ? kEventTypeCount : static_cast<std::size_t>(EventType::elevation);
}
inline constexpr std::uint32_t kBlockMagic = 0x4B42534Du;  // "MSBK"
inline constexpr std::size_t kBlockHeaderSize = 56;
inline constexpr std::size_t kMaxBlockPayload = std::size_t{1} << 30;

enum class BlockKind : std::uint8_t { events = 1, keyframe = 2, end = 3 };

struct BlockHeader {
  BlockKind kind = BlockKind::events;
  std::uint32_t stored_size = 0;
  std::uint32_t raw_size = 0;
  std::uint64_t first_event = 0;
  std::uint64_t count = 0;
  std::uint64_t mesh_hash = 0;
  std::uint32_t steps = 0;
  std::uint64_t checksum = 0;
};

// 64-bit checksum of a byte range; changing any single 8-byte word always changes it.
std::uint64_t checksum(std::span<const std::uint8_t> bytes, std::uint64_t seed = 0);

// The same checksum of `size` bytes taken in pieces (a file read a buffer at a time, rather
// than into memory whole): every piece but the last a multiple of 8 bytes.
class ChecksumStream {
 public:
  explicit ChecksumStream(std::uint64_t size, std::uint64_t seed = 0);
  // Throws std::logic_error for a piece after one that was not a multiple of 8 bytes.
  void add(std::span<const std::uint8_t> piece);
  std::uint64_t value() const;  // once all `size` bytes were added

 private:
  std::uint64_t h_;
  std::uint64_t tail_ = 0;
  bool ended_ = false;  // a piece of a length not a multiple of 8 came: it was the last
};

void serialize(const BlockHeader& h, std::uint8_t out[kBlockHeaderSize]);
BlockHeader parse_block_header(const std::uint8_t in[kBlockHeaderSize]);
// Whether the header's own 32-bit check (over its first 44 bytes) holds.
bool header_intact(const std::uint8_t in[kBlockHeaderSize]);
// Checksum over the first 48 header bytes (checksum field excluded) and the payload.
std::uint64_t block_checksum(const std::uint8_t header[kBlockHeaderSize],
                             std::span<const std::uint8_t> payload);

template <class T>
void put_le(std::vector<std::uint8_t>& out, T value) {
  const std::size_t at = out.size();
  out.resize(at + sizeof(T));
  std::memcpy(out.data() + at, &value, sizeof(T));
}
template <class T>
T get_le(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

inline std::uint64_t zigzag(std::int64_t v) {
  return (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63);
}
inline std::int64_t unzigzag(std::uint64_t v) {
  return static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1);
}

// zstd with a context kept across blocks (a context costs megabytes to set up).
class Compressor {
 public:
  explicit Compressor(int level);
  ~Compressor();
  Compressor(const Compressor&) = delete;
  Compressor& operator=(const Compressor&) = delete;
  void compress(std::span<const std::uint8_t> raw, std::vector<std::uint8_t>& out);

 private:
  void* context_;
  int level_;
};

// The most a compressed block may decompress to. meshstep compresses only events blocks,
// cut at LogWriterOptions::block_bytes (256 KiB) plus one event (a Bowyer-Watson cavity of a
// million faces takes about 20 MB); keyframes, which grow with the mesh, are stored as is.
inline constexpr std::size_t kMaxCompressedRawSize = std::size_t{1} << 30;

class Decompressor {
 public:
  Decompressor();
  ~Decompressor();
  Decompressor(const Decompressor&) = delete;
  Decompressor& operator=(const Decompressor&) = delete;
  // Throws std::runtime_error when the data does not decompress to exactly raw_size bytes,
  // or a compressed payload claims more than kMaxCompressedRawSize.
  void decompress(std::span<const std::uint8_t> stored, std::size_t raw_size,
                  std::vector<std::uint8_t>& out);

 private:
  void* context_;
};

}  // namespace meshstep::replay::format
