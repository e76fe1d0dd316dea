// A greyscale PNG as heights (meshstep/terrain/height_grid.hpp). stb_image decodes the
// pixels at their own bit depth (8 or 16 bits a channel); the rules for what they mean
// are here.
#include <stb/stb_image.h>

#include <array>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/huge_pages.hpp"
#include "io/grid_cells.hpp"
#include "terrain/height_grid_readers.hpp"

namespace meshstep::terrain::detail {
namespace {

constexpr std::array<unsigned char, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
// The IEND chunk, always the last 12 bytes of a whole PNG: no data, and its fixed CRC.
constexpr std::array<unsigned char, 12> kIend = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};

std::vector<unsigned char> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  return bytes;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

void check_options(const HeightGridOptions& options) {
  if (!(options.png_cell > 0.0 && std::isfinite(options.png_cell)))
    throw InputError("the PNG cell size must be a positive number of metres, not " + number(options.png_cell));
  if (!(options.png_z_scale > 0.0 && std::isfinite(options.png_z_scale)))
    throw InputError("the PNG height scale must be a positive number, not " + number(options.png_z_scale));
}

// Pixels of `channels` channels of type T (stbi_uc or stbi_us) into heights: grey is the
// first channel, a fully transparent pixel has no data, and a coloured pixel is refused.
template <class T>
void take_pixels(const std::string& path, const T* pixels, int channels, double full_scale, double z_scale,
                 HeightGrid& grid) {
  const bool has_alpha = channels == 2 || channels == 4;
  const bool has_colour = channels >= 3;
  resize_huge(grid.z, grid.nx * grid.ny);  // the one allocation
  for (std::size_t y = 0; y < grid.ny; ++y) {
    const std::size_t j = grid.ny - 1 - y;  // the picture's top row is the grid's northernmost
    for (std::size_t i = 0; i < grid.nx; ++i) {
      const T* p = pixels + (y * grid.nx + i) * static_cast<std::size_t>(channels);
      if (has_colour && (p[1] != p[0] || p[2] != p[0]))
        throw InputError(path, 0,
                         "pixel (" + std::to_string(i) + ", " + std::to_string(y) + ") is coloured (R, G, B = " +
                             std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) +
                             "): a heightmap must be grey; colour encodings of heights are not read");
      grid.z[j * grid.nx + i] = has_alpha && p[channels - 1] == 0
                                    ? std::numeric_limits<float>::quiet_NaN()
                                    : static_cast<float>(static_cast<double>(p[0]) / full_scale * z_scale);
    }
  }
}

}  // namespace

HeightGrid read_png_heightmap(const std::string& path, const HeightGridOptions& options) {
  check_options(options);
  if (options.geographic.value_or(false))
    throw InputError(path, 0, "a PNG heightmap has no position on Earth: it cannot be read as geographic");
  const std::vector<unsigned char> bytes = read_bytes(path);
  // stb_image reads other formats too (a JPEG's heights would be lossy) and may decode
  // a cut-off file's pixels that are there: both are refused here.
  if (bytes.size() < kPngSignature.size() || !std::equal(kPngSignature.begin(), kPngSignature.end(), bytes.begin()))
    throw InputError(path, 0, "not a PNG file");
  if (bytes.size() < kPngSignature.size() + kIend.size() ||
      !std::equal(kIend.begin(), kIend.end(), bytes.end() - static_cast<std::ptrdiff_t>(kIend.size())))
    throw InputError(path, 0, "truncated or damaged: the file does not end with the IEND chunk");
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw InputError(path, 0, "the file is too large to decode");
  const int size = static_cast<int>(bytes.size());

  const bool sixteen = stbi_is_16_bit_from_memory(bytes.data(), size) != 0;
  int width = 0, height = 0, channels = 0;
  // The header's size, checked as every grid reader checks it, before stb_image makes room.
  if (stbi_info_from_memory(bytes.data(), size, &width, &height, &channels) && width > 0 && height > 0)
    io::detail::checked_grid_cells(path, 0, static_cast<std::uint64_t>(width), static_cast<std::uint64_t>(height),
                                   std::nullopt);
  struct Freer {
    void operator()(void* p) const { stbi_image_free(p); }
  };
  std::unique_ptr<void, Freer> pixels(
      sixteen ? static_cast<void*>(stbi_load_16_from_memory(bytes.data(), size, &width, &height, &channels, 0))
              : static_cast<void*>(stbi_load_from_memory(bytes.data(), size, &width, &height, &channels, 0)));
  if (!pixels) throw InputError(path, 0, std::string("cannot decode the PNG: ") + stbi_failure_reason());
  if (width < 2 || height < 2)
    throw InputError(path, 0, too_few_samples(static_cast<std::size_t>(width), static_cast<std::size_t>(height)));

  HeightGrid grid;
  grid.nx = static_cast<std::size_t>(width);
  grid.ny = static_cast<std::size_t>(height);
  grid.dx = grid.dy = options.png_cell;
  if (sixteen)
    take_pixels(path, static_cast<const stbi_us*>(pixels.get()), channels, 65535.0, options.png_z_scale, grid);
  else
    take_pixels(path, static_cast<const stbi_uc*>(pixels.get()), channels, 255.0, options.png_z_scale, grid);
  pixels.reset();
  if (grid.data_count() == 0) throw InputError(path, 0, "every pixel is fully transparent: the heightmap has no data");

  char note[160];
  std::snprintf(note, sizeof note, "%d-bit PNG: %.9g m cells, heights raw / %d x %.9g", sixteen ? 16 : 8,
                options.png_cell, sixteen ? 65535 : 255, options.png_z_scale);
  grid.units_note = note;
  return grid;
}

}  // namespace meshstep::terrain::detail
