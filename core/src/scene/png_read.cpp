// PNG decoding: the file's structure is checked here (so that a truncated or damaged file
// is reported as such, with where), the pixels are decoded by stb_image (every colour type,
// bit depth and interlacing, converted to 8-bit RGBA).
#include <stb/stb_image.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/scene/image.hpp"
#include "scene/png_format.hpp"

namespace meshstep::scene {

namespace png = detail::png;

namespace {

std::vector<std::uint8_t> read_whole_file(const std::string& path) {
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Closer> file(std::fopen(path.c_str(), "rb"));
  if (!file) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  std::vector<std::uint8_t> bytes;
  std::uint8_t buffer[1 << 16];
  for (;;) {
    const std::size_t n = std::fread(buffer, 1, sizeof buffer, file.get());
    bytes.insert(bytes.end(), buffer, buffer + n);
    if (n < sizeof buffer) break;
  }
  if (std::ferror(file.get())) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  return bytes;
}

std::string chunk_name(const std::uint8_t* type) {
  std::string name;
  for (int i = 0; i < 4; ++i) name += (type[i] >= 0x20 && type[i] < 0x7F) ? static_cast<char>(type[i]) : '?';
  return name;
}

// Walks the chunks: IHDR first, each one whole with a matching CRC, IEND last. Throws
// InputError("PATH: why") naming the chunk and its offset.
void check_structure(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() < png::kSignature.size() ||
      std::memcmp(bytes.data(), png::kSignature.data(), png::kSignature.size()) != 0)
    throw InputError(path, 0, "not a PNG file");
  std::size_t at = png::kSignature.size();
  bool first = true;
  for (;;) {
    if (bytes.size() - at < png::kChunkOverhead)
      throw InputError(path, 0, "truncated: the file ends at byte " + std::to_string(bytes.size()) +
                                    " before the IEND chunk");
    const std::uint32_t length = png::load_u32_be(&bytes[at]);
    const std::uint8_t* type = &bytes[at + 4];
    const std::string name = chunk_name(type);
    if (length > png::kMaxChunkLength)
      throw InputError(path, 0, "corrupt: chunk " + name + " at byte " + std::to_string(at) + " has a bad length");
    if (bytes.size() - at - png::kChunkOverhead < length)
      throw InputError(path, 0, "truncated: chunk " + name + " at byte " + std::to_string(at) + " needs " +
                                    std::to_string(length + png::kChunkOverhead) + " bytes, the file has " +
                                    std::to_string(bytes.size() - at) + " left");
    if (first && name != "IHDR") throw InputError(path, 0, "corrupt: the first chunk is " + name + ", not IHDR");
    const std::uint32_t stored_crc = png::load_u32_be(type + 4 + length);
    if (png::chunk_crc(type, 4 + std::size_t{length}) != stored_crc)
      throw InputError(path, 0, "corrupt: chunk " + name + " at byte " + std::to_string(at) + " fails its CRC");
    at += png::kChunkOverhead + length;
    first = false;
    if (name == "IEND") return;
  }
}

}  // namespace

Image read_png(const std::string& path) {
  const std::vector<std::uint8_t> bytes = read_whole_file(path);
  check_structure(path, bytes);
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw InputError(path, 0, "the file is too large to decode");

  int width = 0, height = 0, channels_in_file = 0;
  struct Freer {
    void operator()(stbi_uc* p) const { stbi_image_free(p); }
  };
  std::unique_ptr<stbi_uc, Freer> pixels(stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width,
                                                               &height, &channels_in_file, 4));
  if (!pixels) throw InputError(path, 0, std::string("cannot decode the PNG: ") + stbi_failure_reason());

  Image image;
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels.get(), pixels.get() + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  return image;
}

}  // namespace meshstep::scene
