// A replay log's bytes made easy for a fuzzer to go deep into: payloads stored raw (the
// format allows a payload stored as is when its stored size equals its raw size) and the
// checksums recomputed after a mutation, so that a mutated event reaches the decoder
// instead of stopping at a checksum mismatch. Uses the format's own helpers
// (core/src/replay/format.hpp).
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "replay/format.hpp"

namespace meshstep::fuzz {

namespace format = replay::format;

// Walks the file header and the block headers; `visit(header_at, payload_at, stored_size)`
// for each block whose header fits (stops at the first that does not).
template <class Visit>
void walk_blocks(std::vector<std::uint8_t>& bytes, Visit&& visit) {
  if (bytes.size() < 16) return;
  const std::uint32_t length = format::get_le<std::uint32_t>(bytes.data() + 12);
  std::size_t at = 16 + std::size_t{length} + 8;
  if (at > bytes.size()) return;
  const std::uint64_t sum = format::checksum({bytes.data(), 16 + std::size_t{length}});
  std::memcpy(bytes.data() + 16 + length, &sum, 8);
  while (at + format::kBlockHeaderSize <= bytes.size()) {
    const std::uint32_t stored = format::get_le<std::uint32_t>(bytes.data() + at + 8);
    if (stored > bytes.size() - at - format::kBlockHeaderSize) return;
    if (!visit(at, at + format::kBlockHeaderSize, stored)) return;
    at += format::kBlockHeaderSize + stored;
  }
}

// Makes every checksum (the file header's, each block header's own check and each block's)
// match the bytes as they are.
inline void fix_checksums(std::vector<std::uint8_t>& bytes) {
  walk_blocks(bytes, [&](std::size_t header, std::size_t payload, std::uint32_t stored) {
    std::uint8_t* h = bytes.data() + header;
    const auto check = static_cast<std::uint32_t>(format::checksum({h, 44}));
    std::memcpy(h + 44, &check, 4);
    const std::uint64_t sum = format::block_checksum(h, {bytes.data() + payload, stored});
    std::memcpy(h + 48, &sum, 8);
    return true;
  });
}

// The same log with every compressed payload stored decompressed, checksums remade.
inline std::vector<std::uint8_t> with_raw_payloads(std::vector<std::uint8_t> bytes) {
  std::vector<std::uint8_t> out;
  std::size_t copied = 0;
  format::Decompressor unzip;
  std::vector<std::uint8_t> raw;
  walk_blocks(bytes, [&](std::size_t header, std::size_t payload, std::uint32_t stored) {
    const std::uint32_t raw_size = format::get_le<std::uint32_t>(bytes.data() + header + 12);
    out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(copied),
               bytes.begin() + static_cast<std::ptrdiff_t>(payload));
    if (stored != raw_size) {
      unzip.decompress({bytes.data() + payload, stored}, raw_size, raw);
      std::memcpy(out.data() + out.size() - format::kBlockHeaderSize + 8, &raw_size, 4);  // stored = raw
      out.insert(out.end(), raw.begin(), raw.end());
    } else {
      out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(payload),
                 bytes.begin() + static_cast<std::ptrdiff_t>(payload + stored));
    }
    copied = payload + stored;
    return true;
  });
  out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(copied), bytes.end());
  fix_checksums(out);
  return out;
}

}  // namespace meshstep::fuzz
