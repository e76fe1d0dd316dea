// The pieces of the PNG format (ISO/IEC 15948, W3C PNG specification) that both the
// encoder and the reader's structure check use: the signature and the chunk framing.
//
// A PNG file is the 8-byte signature followed by chunks. A chunk is its data length
// (4 bytes, big-endian, at most 2^31 - 1), a 4-letter type, the data, and a CRC-32 of the
// type and the data. IHDR comes first, IEND last; the pixels are the zlib stream that the
// IDAT chunks carry, concatenated.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace meshstep::scene::detail::png {

inline constexpr std::array<std::uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
inline constexpr std::uint32_t kMaxChunkLength = 0x7FFFFFFFu;
// Length, type and CRC around a chunk's data.
inline constexpr std::size_t kChunkOverhead = 12;

// IHDR colour types this project writes (8 bits per channel).
inline constexpr std::uint8_t kColorTypeRgb = 2;
inline constexpr std::uint8_t kColorTypeRgba = 6;

inline std::uint32_t load_u32_be(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | std::uint32_t{p[3]};
}

inline void append_u32_be(std::vector<std::uint8_t>& out, std::uint32_t v) {
  out.insert(out.end(), {static_cast<std::uint8_t>(v >> 24), static_cast<std::uint8_t>(v >> 16),
                         static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)});
}

// CRC-32 of a chunk's type and data (zlib's crc32, the one the specification prescribes).
std::uint32_t chunk_crc(const std::uint8_t* type_and_data, std::size_t size);

// Appends a whole chunk: length, type, data, CRC. `data.size()` must fit kMaxChunkLength.
void append_chunk(std::vector<std::uint8_t>& out, std::string_view type, const std::uint8_t* data, std::size_t size);

}  // namespace meshstep::scene::detail::png
