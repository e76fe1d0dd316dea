// Tolerant image comparison for the golden-image tests.
#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "meshstep/scene/image.hpp"

namespace meshstep::scene {

namespace {

constexpr std::uint8_t kMarkRed[4] = {255, 0, 0, 255};

void check_consistent(const Image& image, const char* which) {
  if (image.width < 0 || image.height < 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4)
    throw std::invalid_argument(std::string("compare_images: the ") + which + " image's rgba is not width * height * 4");
}

// Expected, mixed three quarters of the way to white: the backdrop the red marks stand out on.
void faded(const std::uint8_t* in, std::uint8_t* out) {
  for (int c = 0; c < 3; ++c) out[c] = static_cast<std::uint8_t>(255 - (255 - in[c]) / 4);
  out[3] = 255;
}

}  // namespace

ImageDiff compare_images(const Image& expected, const Image& actual, int tolerance) {
  check_consistent(expected, "expected");
  check_consistent(actual, "actual");

  // Sizes that differ are compared over the rectangle covering both: a pixel that only one
  // image has differs by 255, so a size mismatch never passes as "0 pixels differ".
  ImageDiff diff;
  diff.same_size = expected.width == actual.width && expected.height == actual.height;
  const int width = std::max(expected.width, actual.width), height = std::max(expected.height, actual.height);
  diff.picture.width = width;
  diff.picture.height = height;
  diff.picture.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);

  for (int y = 0; y < height; ++y) {
    std::uint8_t* out = diff.picture.row(y);
    for (int x = 0; x < width; ++x, out += 4) {
      const bool in_expected = x < expected.width && y < expected.height;
      const bool in_actual = x < actual.width && y < actual.height;
      if (!in_expected || !in_actual) {
        ++diff.differing_pixels;
        diff.max_channel_delta = 255;
        std::copy_n(kMarkRed, 4, out);
        continue;
      }
      const std::uint8_t* e = expected.row(y) + static_cast<std::size_t>(x) * 4;
      const std::uint8_t* a = actual.row(y) + static_cast<std::size_t>(x) * 4;
      int delta = 0;
      for (int c = 0; c < 4; ++c) delta = std::max(delta, std::abs(int{e[c]} - int{a[c]}));
      diff.max_channel_delta = std::max(diff.max_channel_delta, delta);
      if (delta > tolerance) {
        ++diff.differing_pixels;
        std::copy_n(kMarkRed, 4, out);
      } else {
        faded(e, out);
      }
    }
  }
  return diff;
}

}  // namespace meshstep::scene
