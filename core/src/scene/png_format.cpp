#include "scene/png_format.hpp"

#include <zlib.h>

#include <climits>

namespace meshstep::scene::detail::png {

std::uint32_t chunk_crc(const std::uint8_t* type_and_data, std::size_t size) {
  // crc32 takes a uInt length: feed huge chunks in pieces.
  uLong crc = crc32(0L, Z_NULL, 0);
  while (size > 0) {
    const uInt piece = size > UINT_MAX ? UINT_MAX : static_cast<uInt>(size);
    crc = crc32(crc, type_and_data, piece);
    type_and_data += piece;
    size -= piece;
  }
  return static_cast<std::uint32_t>(crc);
}

void append_chunk(std::vector<std::uint8_t>& out, std::string_view type, const std::uint8_t* data, std::size_t size) {
  append_u32_be(out, static_cast<std::uint32_t>(size));
  const std::size_t type_at = out.size();
  out.insert(out.end(), type.begin(), type.end());
  if (size > 0) out.insert(out.end(), data, data + size);
  append_u32_be(out, chunk_crc(out.data() + type_at, out.size() - type_at));
}

}  // namespace meshstep::scene::detail::png
