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

// The PNG file's bytes. compression_level: zlib's 1 (fast) .. 9 (small).
std::vector<std::uint8_t> encode_png(const Image& image, int compression_level = 6);
// Writes PATH atomically (a temporary file beside it, renamed into place); throws
// InputError("PATH: why") when it cannot.
void write_png(const std::string& path, const Image& image, int compression_level = 6);
// Throws InputError("PATH: why") when the file is missing or not a PNG.
Image read_png(const std::string& path);

// How two images of one size differ: pixels with some channel differing by more than
// `tolerance`, the largest channel difference, and a picture of where (the differing
// pixels in red over a faded copy of `expected`).
struct ImageDiff {
  bool same_size = true;
  std::size_t differing_pixels = 0;
  int max_channel_delta = 0;
  Image picture;
};
ImageDiff compare_images(const Image& expected, const Image& actual, int tolerance);

}  // namespace meshstep::scene
