// PNG encoding: our own small encoder over zlib, written from the PNG specification.
//
// Why not stb_image_write: frame export needs >= 30 frames/s of 1280x720 on 2 cores, so at
// most about 50 ms per frame on one core. stb's encoder tries all five filters on every row
// and deflates with a simple compressor of its own: 75-250 ms per synthetic 1280x720 mesh
// frame (CPU time; its level and forced filters change little). This one takes 10-35 ms at
// level 1 on the same frames (sparse to dense meshes), 25-90 ms at level 6.
//
// Choices, measured on rendered-mesh pictures (flat triangles, antialiased edges):
//   - Filter type 0 (none) on every row. Deflate already finds the flat colour runs
//     (matches at distance 3 or 4) and the row above (distance = one row, inside its 32 KiB
//     window); the sub / up / Paeth filters (one per picture, or sub-or-up chosen per row by
//     the smaller sum of differences) turn antialiased edges into noise: files 15-40% larger,
//     and encoding slower at every level.
//   - RGB instead of RGBA when every pixel is opaque (rendered frames are): a quarter less
//     to compress, and a reader gets the same RGBA back.
//   - zlib's default strategy: Z_RLE is faster at levels >= 3 but needs a filter to find
//     anything, and is then larger than level 1 unfiltered.
#include <zlib.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

#include "meshstep/io/atomic_file.hpp"
#include "meshstep/scene/image.hpp"
#include "scene/png_format.hpp"

namespace meshstep::scene {

namespace png = detail::png;

namespace {

constexpr std::uint8_t kFilterNone = 0;
// How much compressed data one IDAT chunk carries (any size is valid; this bounds the buffer).
constexpr std::size_t kIdatPieceBytes = std::size_t{1} << 18;

void check_encodable(const Image& image) {
  if (image.width < 1 || image.height < 1)
    throw std::invalid_argument("encode_png: the image is empty (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ")");
  // PNG stores sizes in 31 bits.
  if (static_cast<std::uint32_t>(image.width) > png::kMaxChunkLength ||
      static_cast<std::uint32_t>(image.height) > png::kMaxChunkLength)
    throw std::invalid_argument("encode_png: the image is too large for PNG");
  if (image.rgba.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4)
    throw std::invalid_argument("encode_png: rgba holds " + std::to_string(image.rgba.size()) +
                                " bytes, not width * height * 4");
}

bool every_pixel_opaque(const Image& image) {
  for (std::size_t i = 3; i < image.rgba.size(); i += 4)
    if (image.rgba[i] != 255) return false;
  return true;
}

std::vector<std::uint8_t> header_data(const Image& image, std::uint8_t color_type) {
  std::vector<std::uint8_t> ihdr;
  png::append_u32_be(ihdr, static_cast<std::uint32_t>(image.width));
  png::append_u32_be(ihdr, static_cast<std::uint32_t>(image.height));
  // Bit depth 8, colour type, compression 0 (deflate), filter method 0, no interlace.
  ihdr.insert(ihdr.end(), {8, color_type, 0, 0, 0});
  return ihdr;
}

// The zlib stream of the pixels, cut into IDAT chunks appended to `file` as it is produced.
class IdatWriter {
 public:
  IdatWriter(std::vector<std::uint8_t>& file, int level) : file_(file), piece_(kIdatPieceBytes) {
    if (deflateInit2(&stream_, level, Z_DEFLATED, 15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
      throw std::runtime_error("encode_png: zlib cannot start deflate");
    stream_.next_out = piece_.data();
    stream_.avail_out = static_cast<uInt>(piece_.size());
  }
  ~IdatWriter() { deflateEnd(&stream_); }
  IdatWriter(const IdatWriter&) = delete;
  IdatWriter& operator=(const IdatWriter&) = delete;

  void write(const std::uint8_t* data, std::size_t size) {
    while (size > 0) {
      const uInt piece = size > UINT_MAX ? UINT_MAX : static_cast<uInt>(size);
      stream_.next_in = const_cast<Bytef*>(data);  // zlib's interface is not const-correct
      stream_.avail_in = piece;
      run(Z_NO_FLUSH);
      data += piece;
      size -= piece;
    }
  }

  void finish() {
    stream_.next_in = nullptr;
    stream_.avail_in = 0;
    run(Z_FINISH);
    flush_piece();
  }

 private:
  // Deflates until the input is consumed (or, finishing, until the stream ends), emitting
  // a chunk whenever the output piece fills up.
  void run(int flush) {
    for (;;) {
      const int status = deflate(&stream_, flush);
      if (status == Z_STREAM_ERROR) throw std::runtime_error("encode_png: zlib deflate failed");
      if (stream_.avail_out == 0) {
        flush_piece();
        continue;
      }
      if (flush == Z_FINISH ? status == Z_STREAM_END : stream_.avail_in == 0) return;
    }
  }

  void flush_piece() {
    const std::size_t used = piece_.size() - stream_.avail_out;
    if (used > 0) png::append_chunk(file_, "IDAT", piece_.data(), used);
    stream_.next_out = piece_.data();
    stream_.avail_out = static_cast<uInt>(piece_.size());
  }

  std::vector<std::uint8_t>& file_;
  std::vector<std::uint8_t> piece_;
  z_stream stream_{};
};

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image, int compression_level) {
  check_encodable(image);
  const int level = std::clamp(compression_level, 0, 9);
  const bool opaque = every_pixel_opaque(image);
  const std::size_t channels = opaque ? 3 : 4;

  std::vector<std::uint8_t> file(png::kSignature.begin(), png::kSignature.end());
  const std::vector<std::uint8_t> ihdr = header_data(image, opaque ? png::kColorTypeRgb : png::kColorTypeRgba);
  png::append_chunk(file, "IHDR", ihdr.data(), ihdr.size());

  // Each row is its filter type byte followed by the row's pixels.
  const std::size_t width = static_cast<std::size_t>(image.width);
  std::vector<std::uint8_t> row(1 + width * channels);
  row[0] = kFilterNone;
  IdatWriter idat(file, level);
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* src = image.row(y);
    std::uint8_t* dst = row.data() + 1;
    if (opaque) {
      for (std::size_t x = 0; x < width; ++x, src += 4, dst += 3) std::memcpy(dst, src, 3);
    } else {
      std::memcpy(dst, src, width * 4);
    }
    idat.write(row.data(), row.size());
  }
  idat.finish();

  png::append_chunk(file, "IEND", nullptr, 0);
  return file;
}

void write_png(const std::string& path, const Image& image, int compression_level) {
  const std::vector<std::uint8_t> file = encode_png(image, compression_level);
  io::write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(file.data()), file.size()));
}

}  // namespace meshstep::scene
