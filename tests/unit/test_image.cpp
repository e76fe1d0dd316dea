// PNG in and out, and the tolerant image comparison of the golden-image tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/scene/image.hpp"
#include "temp_dir.hpp"

namespace meshstep::scene {
namespace {

using testing::TempDir;

Image filled(int width, int height, std::array<std::uint8_t, 4> rgba) {
  Image image;
  image.width = width;
  image.height = height;
  for (int i = 0; i < width * height; ++i) image.rgba.insert(image.rgba.end(), rgba.begin(), rgba.end());
  return image;
}

// Noise in every channel (alpha too): no run or repeat for deflate to lean on.
Image noise(int width, int height, bool opaque, unsigned seed) {
  std::mt19937 rng(seed);
  Image image = filled(width, height, {0, 0, 0, 0});
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    image.rgba[i] = opaque && i % 4 == 3 ? 255 : static_cast<std::uint8_t>(rng() & 0xFF);
  return image;
}

std::uint8_t* pixel(Image& image, int x, int y) { return image.row(y) + static_cast<std::size_t>(x) * 4; }

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The InputError's text, checked to name the file first.
std::string read_error(const std::string& path) {
  try {
    read_png(path);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    return e.message();
  }
  ADD_FAILURE() << "read_png(" << path << ") did not throw";
  return "";
}

TEST(Png, RoundTripIsExact) {
  TempDir dir;
  for (const bool opaque : {false, true})
    for (const int level : {0, 1, 6, 9}) {
      const Image image = noise(37, 23, opaque, 7u + level);
      const std::string path = dir.file("noise.png");
      write_png(path, image, level);
      const Image back = read_png(path);
      EXPECT_EQ(back.width, 37);
      EXPECT_EQ(back.height, 23);
      EXPECT_TRUE(back.rgba == image.rgba) << "opaque " << opaque << ", level " << level;
    }
}

TEST(Png, RoundTripOfOnePixelAndOfALargeFlatPicture) {
  TempDir dir;
  for (const Image& image : {filled(1, 1, {1, 2, 3, 4}), filled(1280, 720, {250, 250, 248, 255})}) {
    write_png(dir.file("p.png"), image, 1);
    const Image back = read_png(dir.file("p.png"));
    EXPECT_EQ(back.width, image.width);
    EXPECT_EQ(back.height, image.height);
    EXPECT_TRUE(back.rgba == image.rgba);
  }
}

TEST(Png, OpaquePicturesAreStoredAsRgb) {
  // IHDR's colour type is byte 25 of the file: 8 signature + 4 length + 4 type + 9.
  const std::vector<std::uint8_t> opaque = encode_png(filled(4, 4, {10, 20, 30, 255}), 6);
  const std::vector<std::uint8_t> translucent = encode_png(filled(4, 4, {10, 20, 30, 254}), 6);
  ASSERT_GT(opaque.size(), 26u);
  EXPECT_EQ(opaque[25], 2);       // RGB
  EXPECT_EQ(translucent[25], 6);  // RGBA
}

TEST(Png, EncodeRejectsInconsistentImages) {
  EXPECT_THROW(encode_png(Image{}, 1), std::invalid_argument);
  Image wrong = filled(3, 3, {0, 0, 0, 255});
  wrong.rgba.pop_back();
  EXPECT_THROW(encode_png(wrong, 1), std::invalid_argument);
}

TEST(Png, WriteToAnUnwritablePathThrowsAndLeavesNothing) {
  TempDir dir;
  const Image image = filled(8, 8, {1, 2, 3, 255});
  // A folder that does not exist.
  const std::string missing = dir.file("no_such_folder/picture.png");
  try {
    write_png(missing, image, 1);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), missing);
  }
  EXPECT_TRUE(dir.entries().empty());

  // A path that is a folder: the temporary file is written, the rename fails, and the
  // temporary file is gone again.
  std::filesystem::create_directory(dir.file("taken"));
  EXPECT_THROW(write_png(dir.file("taken"), image, 1), InputError);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken"});
}

TEST(Png, WriteReplacesAnExistingFile) {
  TempDir dir;
  const std::string path = dir.write("p.png", "old contents");
  write_png(path, filled(2, 2, {9, 9, 9, 255}), 1);
  EXPECT_EQ(read_png(path).rgba, filled(2, 2, {9, 9, 9, 255}).rgba);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.png"});
}

TEST(Png, ReadOfAMissingFileNamesIt) {
  TempDir dir;
  EXPECT_NE(read_error(dir.file("absent.png")).find("cannot read"), std::string::npos);
}

TEST(Png, ReadOfGarbageSaysItIsNotAPng) {
  TempDir dir;
  EXPECT_EQ(read_error(dir.write("garbage.png", "this is not a picture at all")), "not a PNG file");
  EXPECT_EQ(read_error(dir.write("empty.png", "")), "not a PNG file");
}

TEST(Png, ReadOfATruncatedFileSaysSo) {
  TempDir dir;
  const std::string path = dir.file("whole.png");
  write_png(path, noise(64, 64, false, 3), 6);
  const std::string whole = read_bytes(path);
  // Within the signature, within IHDR, half way through the pixels, one byte short of the end.
  for (const std::size_t keep : {std::size_t{5}, std::size_t{20}, whole.size() / 2, whole.size() - 1}) {
    const std::string cut = dir.write("cut.png", whole.substr(0, keep));
    const std::string message = read_error(cut);
    const bool explained = message.find("truncated") != std::string::npos || message == "not a PNG file";
    EXPECT_TRUE(explained) << keep << " bytes: " << message;
  }
}

TEST(Png, ReadOfADamagedFileSaysWhichChunk) {
  TempDir dir;
  const std::string path = dir.file("whole.png");
  write_png(path, noise(16, 16, false, 4), 6);
  std::string bytes = read_bytes(path);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5A);  // inside the pixels
  const std::string message = read_error(dir.write("damaged.png", bytes));
  EXPECT_NE(message.find("IDAT"), std::string::npos) << message;
  EXPECT_NE(message.find("CRC"), std::string::npos) << message;
}

TEST(CompareImages, IdenticalPicturesDoNotDiffer) {
  const Image a = noise(20, 10, false, 5);
  const ImageDiff diff = compare_images(a, a, 0);
  EXPECT_TRUE(diff.same_size);
  EXPECT_EQ(diff.differing_pixels, 0u);
  EXPECT_EQ(diff.max_channel_delta, 0);
  EXPECT_EQ(diff.picture.width, 20);
  EXPECT_EQ(diff.picture.height, 10);
}

TEST(CompareImages, CountsExactlyThePixelsBeyondTheTolerance) {
  const Image expected = filled(10, 8, {100, 150, 200, 255});
  Image actual = expected;
  pixel(actual, 1, 1)[0] += 5;   // beyond a tolerance of 4
  pixel(actual, 2, 3)[1] -= 4;   // within it
  pixel(actual, 7, 6)[3] -= 10;  // alpha counts too
  pixel(actual, 9, 7)[2] += 3;   // within
  const ImageDiff diff = compare_images(expected, actual, 4);
  EXPECT_TRUE(diff.same_size);
  EXPECT_EQ(diff.differing_pixels, 2u);
  EXPECT_EQ(diff.max_channel_delta, 10);
  EXPECT_EQ(compare_images(expected, actual, 10).differing_pixels, 0u);
  EXPECT_EQ(compare_images(expected, actual, 0).differing_pixels, 4u);

  // Red where they differ, elsewhere expected faded three quarters of the way to white.
  Image picture = diff.picture;
  const std::vector<std::uint8_t> red = {255, 0, 0, 255};
  EXPECT_EQ(std::vector<std::uint8_t>(pixel(picture, 1, 1), pixel(picture, 1, 1) + 4), red);
  EXPECT_EQ(std::vector<std::uint8_t>(pixel(picture, 7, 6), pixel(picture, 7, 6) + 4), red);
  const std::vector<std::uint8_t> faded = {255 - 155 / 4, 255 - 105 / 4, 255 - 55 / 4, 255};
  EXPECT_EQ(std::vector<std::uint8_t>(pixel(picture, 2, 3), pixel(picture, 2, 3) + 4), faded);
  EXPECT_EQ(std::vector<std::uint8_t>(pixel(picture, 0, 0), pixel(picture, 0, 0) + 4), faded);
}

TEST(CompareImages, ReportsASizeMismatchWithoutPassingIt) {
  const Image wide = filled(4, 3, {1, 1, 1, 255});
  const Image tall = filled(3, 4, {1, 1, 1, 255});
  const ImageDiff diff = compare_images(wide, tall, 255);
  EXPECT_FALSE(diff.same_size);
  // Over the 4x4 rectangle covering both, the 3x3 they share is equal: 7 pixels differ.
  EXPECT_EQ(diff.differing_pixels, 7u);
  EXPECT_EQ(diff.max_channel_delta, 255);
  EXPECT_EQ(diff.picture.width, 4);
  EXPECT_EQ(diff.picture.height, 4);

  const ImageDiff against_nothing = compare_images(wide, Image{}, 0);
  EXPECT_FALSE(against_nothing.same_size);
  EXPECT_EQ(against_nothing.differing_pixels, 12u);
}

}  // namespace
}  // namespace meshstep::scene
