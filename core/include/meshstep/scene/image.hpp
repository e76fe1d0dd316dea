// Pictures as pixels: the RGBA image every renderer produces, PNG in and out, and the
// tolerant comparison the golden-image tests use.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace meshstep::scene {

// 8-bit RGBA, rows top to bottom (as images are stored; GL read-back is flipped into this).
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4

  std::uint8_t* row(int y) { return rgba.data() + static_cast<std::size_t>(y) * width * 4; }
  const std::uint8_t* row(int y) const { return rgba.data() + static_cast<std::size_t>(y) * width * 4; }
};

// The PNG file's bytes. compression_level: zlib's 1 (fast) .. 9 (small); 0 stores the
// pixels uncompressed, values outside 0..9 are clamped. An image whose pixels are all
// opaque is stored as RGB (read_png gives the same RGBA back).
//
// Speed, one core, a 1280x720 picture of a mesh (flat triangles, antialiased edges; sparse
// to dense): level 1 takes 10-35 ms (230 KB-1.1 MB), level 6 25-90 ms and 5-10% smaller,
// level 9 55-170 ms. Frame export wants level 1.
//
// Throws std::invalid_argument when the image is empty or rgba is not width * height * 4
// bytes. Thread-safe: frames may be encoded on several threads at once.
std::vector<std::uint8_t> encode_png(const Image& image, int compression_level = 6);
// Writes PATH atomically (a temporary file beside it, renamed into place; on failure the
// target is left as it was and the temporary file removed); throws InputError("PATH: why")
// when it cannot.
void write_png(const std::string& path, const Image& image, int compression_level = 6);
// Any PNG (every colour type and bit depth, interlaced or not) as 8-bit RGBA. Throws
// InputError("PATH: why") when the file is missing or unreadable, not a PNG, truncated, or
// damaged (a chunk's CRC, or undecodable pixels).
Image read_png(const std::string& path);

// How two images of one size differ: pixels with some channel (alpha included) differing
// by more than `tolerance`, the largest channel difference, and a picture of where (the
// differing pixels in red over a faded copy of `expected`).
//
// Images of different sizes are compared over the rectangle covering both: same_size is
// false, and every pixel only one of them has counts as differing (by 255, red in the
// picture), so a size mismatch never passes as "0 pixels differ". Throws
// std::invalid_argument when an image's rgba is not width * height * 4 bytes.
struct ImageDiff {
  bool same_size = true;
  std::size_t differing_pixels = 0;
  int max_channel_delta = 0;
  Image picture;
};
ImageDiff compare_images(const Image& expected, const Image& actual, int tolerance);

}  // namespace meshstep::scene
