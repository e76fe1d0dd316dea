// Checksums, block headers and compression for the replay log.
#include "format.hpp"

#include <zstd.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <new>
#include <stdexcept>

namespace meshstep::replay::format {
namespace {

constexpr std::uint64_t kMul1 = 0x9E3779B97F4A7C15ull;
constexpr std::uint64_t kMul2 = 0xC2B2AE3D27D4EB4Full;

}  // namespace

std::uint64_t checksum(std::span<const std::uint8_t> bytes, std::uint64_t seed) {
  ChecksumStream stream(bytes.size(), seed);
  stream.add(bytes);
  return stream.value();
}

ChecksumStream::ChecksumStream(std::uint64_t size, std::uint64_t seed) : h_(seed ^ (size * kMul1)) {}

void ChecksumStream::add(std::span<const std::uint8_t> piece) {
  // Each step h -> rotl(h ^ w * kMul1, 31) * kMul2 is a bijection of h for a fixed word and
  // of the word for a fixed h (odd multipliers), so a change confined to one word always
  // changes the result.
  if (ended_) throw std::logic_error("checksum: a piece after the last");
  std::uint64_t h = h_;
  std::size_t i = 0;
  for (; i + 8 <= piece.size(); i += 8) {
    std::uint64_t w;
    std::memcpy(&w, piece.data() + i, 8);
    h = std::rotl(h ^ (w * kMul1), 31) * kMul2;
  }
  h_ = h;
  // An empty span may have no data pointer at all, which memcpy must not be given.
  if (i < piece.size()) {
    std::memcpy(&tail_, piece.data() + i, piece.size() - i);
    ended_ = true;
  }
}

std::uint64_t ChecksumStream::value() const {
  std::uint64_t h = std::rotl(h_ ^ (tail_ * kMul1), 31) * kMul2;
  h ^= h >> 33;
  h *= kMul1;
  h ^= h >> 29;
  return h;
}

void serialize(const BlockHeader& h, std::uint8_t out[kBlockHeaderSize]) {
  std::memset(out, 0, kBlockHeaderSize);
  std::memcpy(out + 0, &kBlockMagic, 4);
  out[4] = static_cast<std::uint8_t>(h.kind);
  std::memcpy(out + 8, &h.stored_size, 4);
  std::memcpy(out + 12, &h.raw_size, 4);
  std::memcpy(out + 16, &h.first_event, 8);
  std::memcpy(out + 24, &h.count, 8);
  std::memcpy(out + 32, &h.mesh_hash, 8);
  std::memcpy(out + 40, &h.steps, 4);
  const auto check = static_cast<std::uint32_t>(checksum({out, 44}));
  std::memcpy(out + 44, &check, 4);
  std::memcpy(out + 48, &h.checksum, 8);
}

bool header_intact(const std::uint8_t in[kBlockHeaderSize]) {
  return get_le<std::uint32_t>(in + 44) == static_cast<std::uint32_t>(checksum({in, 44}));
}

BlockHeader parse_block_header(const std::uint8_t in[kBlockHeaderSize]) {
  BlockHeader h;
  h.kind = static_cast<BlockKind>(in[4]);
  h.stored_size = get_le<std::uint32_t>(in + 8);
  h.raw_size = get_le<std::uint32_t>(in + 12);
  h.first_event = get_le<std::uint64_t>(in + 16);
  h.count = get_le<std::uint64_t>(in + 24);
  h.mesh_hash = get_le<std::uint64_t>(in + 32);
  h.steps = get_le<std::uint32_t>(in + 40);
  h.checksum = get_le<std::uint64_t>(in + 48);
  return h;
}

std::uint64_t block_checksum(const std::uint8_t header[kBlockHeaderSize],
                             std::span<const std::uint8_t> payload) {
  return checksum(payload, checksum({header, 48}));
}

Compressor::Compressor(int level) : context_(ZSTD_createCCtx()), level_(level) {
  if (!context_) throw std::bad_alloc();
}
Compressor::~Compressor() { ZSTD_freeCCtx(static_cast<ZSTD_CCtx*>(context_)); }

void Compressor::compress(std::span<const std::uint8_t> raw, std::vector<std::uint8_t>& out) {
  out.resize(ZSTD_compressBound(raw.size()));
  const std::size_t n = ZSTD_compressCCtx(static_cast<ZSTD_CCtx*>(context_), out.data(),
                                          out.size(), raw.data(), raw.size(), level_);
  if (ZSTD_isError(n)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(n));
  out.resize(n);
}

Decompressor::Decompressor() : context_(ZSTD_createDCtx()) {
  if (!context_) throw std::bad_alloc();
}
Decompressor::~Decompressor() { ZSTD_freeDCtx(static_cast<ZSTD_DCtx*>(context_)); }

void Decompressor::decompress(std::span<const std::uint8_t> stored, std::size_t raw_size,
                              std::vector<std::uint8_t>& out) {
  if (stored.size() == raw_size) {  // stored as is
    out.resize(raw_size);
    if (raw_size) std::memcpy(out.data(), stored.data(), raw_size);  // (an empty vector's data() may be null)
    return;
  }
  // A block header can lie about the size (the fuzzer's: 4 GB to zero before a byte was
  // read). So the size is checked against the frame's own and a bound, and the output grows
  // with what the frame really holds, never to the size claimed before the data bears it out.
  if (raw_size > kMaxCompressedRawSize)
    throw std::runtime_error("claims to decompress to " + std::to_string(raw_size) + " bytes, more than the " +
                             std::to_string(kMaxCompressedRawSize) + " a compressed block may hold");
  const unsigned long long framed = ZSTD_getFrameContentSize(stored.data(), stored.size());
  if (framed == ZSTD_CONTENTSIZE_ERROR) throw std::runtime_error("does not decompress (not a zstd frame)");
  if (framed != ZSTD_CONTENTSIZE_UNKNOWN && framed != raw_size)
    throw std::runtime_error("decompresses to " + std::to_string(framed) + " bytes instead of " + std::to_string(raw_size));
  auto* context = static_cast<ZSTD_DCtx*>(context_);
  ZSTD_DCtx_reset(context, ZSTD_reset_session_only);
  constexpr std::size_t kFirstChunk = std::size_t{1} << 20;
  out.resize(std::min(raw_size, kFirstChunk));
  ZSTD_inBuffer in{stored.data(), stored.size(), 0};
  std::size_t produced = 0;
  for (;;) {
    ZSTD_outBuffer o{out.data(), out.size(), produced};
    const std::size_t left = ZSTD_decompressStream(context, &o, &in);
    if (ZSTD_isError(left)) throw std::runtime_error(std::string("does not decompress (") + ZSTD_getErrorName(left) + ")");
    produced = o.pos;
    if (left == 0) break;  // the frame is complete
    if (produced < out.size()) {
      if (in.pos == in.size) throw std::runtime_error("does not decompress (the frame is cut short)");
      continue;
    }
    if (out.size() == raw_size)
      throw std::runtime_error("decompresses to more than " + std::to_string(raw_size) + " bytes");
    out.resize(std::min(raw_size, 2 * out.size()));
  }
  if (produced != raw_size || in.pos != in.size)
    throw std::runtime_error("decompresses to " + std::to_string(produced) + " bytes instead of " +
                             std::to_string(raw_size) + (in.pos != in.size ? ", with bytes left over" : ""));
}

}  // namespace meshstep::replay::format
