// Fixed-size numbers in a given byte order, for the binary surface formats (PLY, STL),
// assembled byte by byte so that the host's own byte order never matters.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

namespace meshstep::io::detail {

// The unsigned integer in the `size` (1, 2, 4 or 8) bytes at p.
inline std::uint64_t load_uint(const std::uint8_t* p, std::size_t size, bool big_endian) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < size; ++i) {
    const std::size_t k = big_endian ? i : size - 1 - i;
    v = (v << 8) | p[k];
  }
  return v;
}

inline float load_float(const std::uint8_t* p, bool big_endian) {
  return std::bit_cast<float>(static_cast<std::uint32_t>(load_uint(p, 4, big_endian)));
}

inline double load_double(const std::uint8_t* p, bool big_endian) {
  return std::bit_cast<double>(load_uint(p, 8, big_endian));
}

// Writes the low `size` bytes of v at out, least significant first.
inline void store_little_endian(char* out, std::uint64_t v, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) out[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

}  // namespace meshstep::io::detail
