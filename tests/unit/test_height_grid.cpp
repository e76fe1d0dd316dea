// Height grids for terrain: ESRI grids (no data, row order, degrees to metres), PNG
// heightmaps (8 and 16 bits, grey stored as colour, transparency), the shared terrain
// files, and every malformed input refused with its file and line.
#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "temp_dir.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

using terrain::HeightGrid;
using terrain::HeightGridOptions;
using terrain::read_height_grid;

// The message of the InputError that reading `path` throws, or "no error".
std::string refusal(const std::string& path, const HeightGridOptions& options = {}) {
  try {
    read_height_grid(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// --- A 16-bit greyscale PNG written by hand (stb_image_write writes 8 bits only) ---------

void append_u32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((v >> shift) & 0xFF);
}

std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const unsigned char b : bytes) {
    crc ^= b;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string chunk(const std::string& type, const std::string& data) {
  std::string out;
  append_u32(out, static_cast<std::uint32_t>(data.size()));
  out += type + data;
  append_u32(out, crc32(type + data));
  return out;
}

// `samples` top row first; the zlib stream is one stored (uncompressed) deflate block.
// `declared_height` other than 0 makes IHDR claim more rows than the data holds.
std::string png16(int width, int height, const std::vector<std::uint16_t>& samples, int declared_height = 0) {
  std::string raw;
  for (int y = 0; y < height; ++y) {
    raw += '\0';  // filter type: none
    for (int x = 0; x < width; ++x) {
      const std::uint16_t v = samples[static_cast<std::size_t>(y * width + x)];
      raw += static_cast<char>(v >> 8);
      raw += static_cast<char>(v & 0xFF);
    }
  }
  std::string zlib = "\x78\x01";
  zlib += '\x01';  // the final block, stored
  const auto n = static_cast<std::uint16_t>(raw.size());
  for (const std::uint16_t v : {n, static_cast<std::uint16_t>(~n)}) {
    zlib += static_cast<char>(v & 0xFF);
    zlib += static_cast<char>(v >> 8);
  }
  zlib += raw;
  std::uint32_t a = 1, b = 0;  // Adler-32
  for (const unsigned char c : raw) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  append_u32(zlib, b << 16 | a);
  std::string ihdr;
  append_u32(ihdr, static_cast<std::uint32_t>(width));
  append_u32(ihdr, static_cast<std::uint32_t>(declared_height != 0 ? declared_height : height));
  ihdr += std::string("\x10\x00\x00\x00\x00", 5);  // 16 bits, grey, deflate, no filter set, not interlaced
  return std::string("\x89PNG\r\n\x1A\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", zlib) + chunk("IEND", "");
}

// An 8-bit PNG of `channels` channels through stb_image_write; `pixels` top row first.
std::string write_png8(const testing::TempDir& dir, const std::string& name, int width, int height, int channels,
                       const std::vector<unsigned char>& pixels) {
  const std::string path = dir.file(name);
  EXPECT_NE(stbi_write_png(path.c_str(), width, height, channels, pixels.data(), width * channels), 0);
  return path;
}

// --- ESRI grids --------------------------------------------------------------------------

TEST(HeightGrid, EsriNoDataIsNaNAndRowsRunSouthFirst) {
  testing::TempDir dir("meshstep_height_");
  const std::string path = dir.write("g.asc",
                                     "ncols 3\nnrows 2\nxllcorner 1000\nyllcorner 2000\ncellsize 2\n"
                                     "NODATA_value -9999\n"
                                     "11 12 -9999\n"    // the northern row: j = 1
                                     "21.5 22 23\n");  // the southern row: j = 0
  const HeightGrid g = read_height_grid(path);
  ASSERT_EQ(g.nx, 3u);
  ASSERT_EQ(g.ny, 2u);
  ASSERT_EQ(g.z.size(), 6u);
  EXPECT_EQ(g.at(0, 0), 21.5f);
  EXPECT_EQ(g.at(1, 0), 22.0f);
  EXPECT_EQ(g.at(2, 0), 23.0f);
  EXPECT_EQ(g.at(0, 1), 11.0f);
  EXPECT_EQ(g.at(1, 1), 12.0f);
  EXPECT_TRUE(std::isnan(g.at(2, 1)));
  for (std::size_t j = 0; j < 2; ++j)
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(g.has_data(i, j), !(i == 2 && j == 1)) << i << ", " << j;
  EXPECT_EQ(g.data_count(), 5u);
  EXPECT_EQ(g.height_range(), std::make_pair(11.0f, 23.0f));
  EXPECT_EQ(g.dx, 2.0);
  EXPECT_EQ(g.dy, 2.0);
  EXPECT_EQ(g.x0, 1001.0);  // sample (0, 0) is the centre of the south-west cell
  EXPECT_EQ(g.y0, 2001.0);
  EXPECT_FALSE(g.geographic);
  EXPECT_TRUE(has(g.units_note, "2 m cells")) << g.units_note;
}

TEST(HeightGrid, DegreeCellsBecomeMetresAtTheCentralLatitude) {
  testing::TempDir dir("meshstep_height_");
  constexpr double kCell = 0.00025;  // 0.9 arc-seconds
  const double along_meridian = terrain::kEarthMeanRadius * kCell * std::numbers::pi / 180.0;
  // Two rows either side of 60 degrees N, where a degree of longitude is half a degree of
  // latitude on a sphere; then the same at 60 degrees S.
  for (const char* south : {"59.99975", "-60.00025"}) {
    const std::string path = dir.write("geo.asc", std::string("ncols 3\nnrows 2\nxllcorner 10\nyllcorner ") + south +
                                                      "\ncellsize 0.00025\n1 2 3\n4 5 6\n");
    const HeightGrid g = read_height_grid(path);
    EXPECT_TRUE(g.geographic) << south;
    EXPECT_DOUBLE_EQ(g.dy, along_meridian);
    EXPECT_NEAR(g.dx / g.dy, 0.5, 1e-9);
    EXPECT_TRUE(has(g.units_note, south[0] == '-' ? "0.9 arc-second cells at 60.0 S" : "0.9 arc-second cells at 60.0 N"))
        << g.units_note;
    EXPECT_TRUE(has(g.units_note, "R = 6371008.8 m")) << g.units_note;
    EXPECT_EQ(g.x0, 10.0 + kCell / 2.0);  // x0, y0 stay in degrees

    HeightGridOptions metres;
    metres.geographic = false;
    const HeightGrid raw = read_height_grid(path, metres);
    EXPECT_FALSE(raw.geographic);
    EXPECT_EQ(raw.dx, kCell);
    EXPECT_EQ(raw.dy, kCell);
    EXPECT_TRUE(has(raw.units_note, "not converted")) << raw.units_note;
  }
  // The same small cells beyond longitude 180 are metres of a grid with its own origin.
  const HeightGrid far = read_height_grid(
      dir.write("far.asc", "ncols 2\nnrows 2\nxllcorner 500\nyllcorner 0\ncellsize 0.00025\n1 2\n3 4\n"));
  EXPECT_FALSE(far.geographic);
  EXPECT_EQ(far.dx, kCell);

  // Half-degree cells are not guessed as degrees, but can be declared so.
  const std::string coarse = dir.write("coarse.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 0.5\n1 2\n3 4\n");
  EXPECT_FALSE(read_height_grid(coarse).geographic);
  EXPECT_EQ(read_height_grid(coarse).dy, 0.5);
  HeightGridOptions degrees;
  degrees.geographic = true;
  const HeightGrid declared = read_height_grid(coarse, degrees);
  EXPECT_TRUE(declared.geographic);
  EXPECT_DOUBLE_EQ(declared.dy, terrain::kEarthMeanRadius * 0.5 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(declared.dx, declared.dy * std::cos(0.5 * std::numbers::pi / 180.0));  // centre at 0.5 N
}

TEST(HeightGrid, SharedJacksboroFaultIsGeographic) {
  const std::filesystem::path path = testing::shared_data() / "terrain" / "jacksboro_fault.asc";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent: skipped";
  const HeightGrid g = read_height_grid(path.string());
  EXPECT_EQ(g.nx, 403u);
  EXPECT_EQ(g.ny, 344u);
  EXPECT_TRUE(g.geographic);
  EXPECT_NEAR(g.dx, 74.4, 0.744);  // within 1%
  EXPECT_NEAR(g.dy, 92.6, 0.926);
  EXPECT_TRUE(has(g.units_note, "3 arc-second cells at 36.6 N: 74.4 m x 92.7 m")) << g.units_note;
  EXPECT_EQ(g.height_range(), std::make_pair(236.0f, 1076.0f));

  HeightGridOptions metres;
  metres.geographic = false;
  const HeightGrid raw = read_height_grid(path.string(), metres);
  EXPECT_FALSE(raw.geographic);
  EXPECT_EQ(raw.dx, 0.000833333333);  // the file's cellsize, untouched
  EXPECT_EQ(raw.dy, 0.000833333333);
  EXPECT_EQ(raw.z, g.z);
}

// --- PNG heightmaps ----------------------------------------------------------------------

TEST(HeightGrid, Png8BitReadsRawOver255TimesScale) {
  testing::TempDir dir("meshstep_height_");
  // Top row first: the picture's top is the grid's north, row j = 1.
  const std::vector<unsigned char> grey = {0, 17, 255, 100, 200, 51};
  HeightGridOptions options;
  options.png_cell = 2.5;
  options.png_z_scale = 10.0;
  const HeightGrid g = read_height_grid(write_png8(dir, "h8.png", 3, 2, 1, grey), options);
  ASSERT_EQ(g.nx, 3u);
  ASSERT_EQ(g.ny, 2u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(g.at(i, 1), static_cast<float>(grey[i] / 255.0 * 10.0)) << i;
    EXPECT_EQ(g.at(i, 0), static_cast<float>(grey[3 + i] / 255.0 * 10.0)) << i;
  }
  EXPECT_EQ(g.at(2, 1), 10.0f);  // white is the full scale
  EXPECT_EQ(g.dx, 2.5);
  EXPECT_EQ(g.dy, 2.5);
  EXPECT_FALSE(g.geographic);
  EXPECT_TRUE(has(g.units_note, "8-bit PNG")) << g.units_note;
}

TEST(HeightGrid, Png16BitKeepsAllSixteenBits) {
  testing::TempDir dir("meshstep_height_");
  const std::vector<std::uint16_t> raw = {0, 1, 65535, 256, 257, 40000};  // 1 and 256/257 need 16 bits
  const HeightGrid g = read_height_grid(dir.write("h16.png", png16(3, 2, raw)));
  ASSERT_EQ(g.nx, 3u);
  ASSERT_EQ(g.ny, 2u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(g.at(i, 1), static_cast<float>(raw[i] / 65535.0)) << i;
    EXPECT_EQ(g.at(i, 0), static_cast<float>(raw[3 + i] / 65535.0)) << i;
  }
  EXPECT_GT(g.at(1, 1), 0.0f);
  EXPECT_LT(g.at(0, 0), g.at(1, 0));
  EXPECT_EQ(g.dx, 1.0);  // the default cell
  EXPECT_TRUE(has(g.units_note, "16-bit PNG")) << g.units_note;
}

TEST(HeightGrid, PngGreyInColourAndTransparency) {
  testing::TempDir dir("meshstep_height_");
  // Grey stored as RGB reads as grey.
  const HeightGrid rgb = read_height_grid(write_png8(dir, "rgb.png", 2, 2, 3, {10, 10, 10, 20, 20, 20, 30, 30, 30, 40, 40, 40}));
  EXPECT_EQ(rgb.at(0, 1), static_cast<float>(10 / 255.0));
  EXPECT_EQ(rgb.at(1, 0), static_cast<float>(40 / 255.0));
  // A fully transparent pixel has no data; a half transparent one has.
  const HeightGrid ga = read_height_grid(write_png8(dir, "ga.png", 2, 2, 2, {10, 255, 20, 0, 30, 128, 40, 255}));
  EXPECT_EQ(ga.data_count(), 3u);
  EXPECT_FALSE(ga.has_data(1, 1));
  EXPECT_EQ(ga.at(0, 0), static_cast<float>(30 / 255.0));
  EXPECT_EQ(ga.at(1, 0), static_cast<float>(40 / 255.0));
}

TEST(HeightGrid, SharedVolcanoPngMatchesItsAscGrid) {
  const std::filesystem::path asc = testing::shared_data() / "terrain" / "volcano.asc";
  const std::filesystem::path png = testing::shared_data() / "terrain" / "volcano.png";
  if (!std::filesystem::exists(asc) || !std::filesystem::exists(png)) GTEST_SKIP() << asc << " or .png is absent: skipped";
  const HeightGrid a = read_height_grid(asc.string());
  const HeightGrid p = read_height_grid(png.string());
  // Same size and not transposed: 87 columns (west to east) by 61 rows in both.
  EXPECT_EQ(a.nx, 87u);
  EXPECT_EQ(a.ny, 61u);
  EXPECT_EQ(p.nx, 87u);
  EXPECT_EQ(p.ny, 61u);
  EXPECT_FALSE(a.geographic);
  EXPECT_EQ(a.dx, 10.0);
  EXPECT_EQ(a.height_range(), std::make_pair(94.0f, 195.0f));
  EXPECT_EQ(p.height_range(), std::make_pair(0.0f, 1.0f));
  // The PNG is the grid scaled from 94..195 to 0..65535: every sample agrees, in place
  // (which also checks that both put north at the top).
  const double tolerance = 101.0 / 65535.0;
  for (std::size_t j = 0; j < a.ny; ++j)
    for (std::size_t i = 0; i < a.nx; ++i)
      ASSERT_NEAR(a.at(i, j), 94.0 + 101.0 * p.at(i, j), tolerance) << "sample " << i << ", " << j;
}

// --- Refusals ----------------------------------------------------------------------------

TEST(HeightGrid, MalformedEsriGridsNameFileAndLine) {
  testing::TempDir dir("meshstep_height_");
  const auto message = [&](const std::string& text, const HeightGridOptions& options = {}) {
    return refusal(dir.write("bad.asc", text), options);
  };
  const std::string header = "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n";  // lines 1-5
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"ncols 2.5\nnrows 2\n", "bad.asc:1: ncols should be an integer"},
      {"ncols 3\nnrows -2\n", "bad.asc:2: nrows is negative"},
      {"ncols 0\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n", "bad.asc:1: ncols must be positive"},
      {"ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 0\n1 2 3\n4 5 6\n", "bad.asc:5: cellsize must be positive"},
      {"ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize -1\n1 2 3\n4 5 6\n", "bad.asc:5: cellsize must be positive"},
      {header + "1 2 3\n4 nan 6\n", "bad.asc:7: grid value should be a finite number, found 'nan'"},
      {header + "1 -inf 3\n4 5 6\n", "bad.asc:6: grid value should be a finite number, found '-inf'"},
      {header + "1 2 3\n4 5 6\n7\n", "bad.asc:8: more values than ncols x nrows = 6"},
      // Fewer values than the file's bytes can hold: refused at the counts, before any is read.
      {header + "1 2 3\n4 5\n", "bad.asc:2: 3 x 2 = 6 values, but the file can hold at most 5"},
      {header, "bad.asc:2: 3 x 2 = 6 values, but the file can hold at most 0"},
      // Bytes enough (long numbers), values too few: found at the end.
      {header + "1000 2000 3000\n4000 5000\n", "bad.asc:7: the grid has 5 values; ncols x nrows = 6"},
      {"ncols 3\nnrows 2\nxllcor", "bad.asc:3: the header has no xllcorner or xllcenter"},
      {header + "NODATA_value -9999\n-9999 -9999 -9999\n-9999 -9999 -9999\n",
       "bad.asc:6: every value is NODATA_value (-9999): the grid has no data"},
      {header + "1 2 3\n4 1e39 6\n", "bad.asc:7: grid value 1e+39 is beyond the range of a float"},
      {"ncols 1\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1\n2\n3\n",
       "bad.asc:1: 1 x 3 samples: a terrain needs at least 2 x 2 samples"},
      {"ncols 3\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n",
       "bad.asc:2: 3 x 1 samples: a terrain needs at least 2 x 2 samples"},
  };
  for (const Case& c : cases) EXPECT_TRUE(has(message(c.text), c.expected)) << message(c.text) << "\nexpected " << c.expected;

  // Declared as degrees, a grid must lie within latitudes -90..90 (yllcorner is line 4).
  HeightGridOptions degrees;
  degrees.geographic = true;
  EXPECT_TRUE(has(message("ncols 2\nnrows 2\nxllcorner 0\nyllcorner 89.5\ncellsize 0.5\n1 2\n3 4\n", degrees),
                  "bad.asc:4: read as degrees, the grid spans latitudes 89.5 to 90.5, beyond -90..90"));

  EXPECT_TRUE(has(refusal(dir.file("absent.asc")), dir.file("absent.asc") + ": cannot open"))
      << refusal(dir.file("absent.asc"));
  // Another name: GDAL decides when meshstep has it (its ESRI driver knows this one), else
  // the name is refused.
  const std::string txt = dir.write("grid.txt", header + "1 2 3\n4 5 6\n");
#ifdef MESHSTEP_HAVE_GDAL
  EXPECT_EQ(read_height_grid(txt).z, read_height_grid(dir.write("grid.asc", header + "1 2 3\n4 5 6\n")).z);
  const std::string prose = dir.write("notes.txt", "these are not heights\n");
  EXPECT_TRUE(has(refusal(prose), prose + ": GDAL cannot read it")) << refusal(prose);
#else
  EXPECT_TRUE(has(refusal(txt), txt + ": cannot tell the height grid's format")) << refusal(txt);
#endif
}

TEST(HeightGrid, MalformedPngsNameTheFile) {
  testing::TempDir dir("meshstep_height_");
  const std::string good = png16(2, 2, {1, 2, 3, 4});
  ASSERT_EQ(read_height_grid(dir.write("good.png", good)).nx, 2u);

  const std::string text = dir.write("text.png", "ncols 2\n");
  EXPECT_EQ(refusal(text), text + ": not a PNG file");
  const std::string cut = dir.write("cut.png", good.substr(0, good.size() / 2));
  EXPECT_EQ(refusal(cut), cut + ": truncated or damaged: the file does not end with the IEND chunk");
  // Whole chunks, but IHDR promises 5 rows and the pixels hold 2.
  const std::string short_rows = dir.write("rows.png", png16(2, 2, {1, 2, 3, 4}, 5));
  EXPECT_TRUE(has(refusal(short_rows), short_rows + ": cannot decode the PNG: ")) << refusal(short_rows);
  const std::string narrow = dir.write("narrow.png", png16(1, 3, {1, 2, 3}));
  EXPECT_EQ(refusal(narrow), narrow + ": 1 x 3 samples: a terrain needs at least 2 x 2 samples");
  const std::string clear = write_png8(dir, "clear.png", 2, 2, 2, {10, 0, 20, 0, 30, 0, 40, 0});
  EXPECT_EQ(refusal(clear), clear + ": every pixel is fully transparent: the heightmap has no data");
  const std::string colour = write_png8(dir, "colour.png", 2, 2, 3, {5, 5, 5, 9, 8, 9, 1, 1, 1, 2, 2, 2});
  EXPECT_TRUE(has(refusal(colour), colour + ": pixel (1, 0) is coloured (R, G, B = 9, 8, 9)")) << refusal(colour);

  const std::string path = dir.write("ok.png", good);
  HeightGridOptions degrees;
  degrees.geographic = true;
  EXPECT_TRUE(has(refusal(path, degrees), path + ": a PNG heightmap has no position on Earth")) << refusal(path, degrees);
  HeightGridOptions flat_cells;
  flat_cells.png_cell = 0.0;
  EXPECT_TRUE(has(refusal(path, flat_cells), "cell size must be a positive number of metres, not 0"))
      << refusal(path, flat_cells);
  HeightGridOptions no_scale;
  no_scale.png_z_scale = -1.0;
  EXPECT_TRUE(has(refusal(path, no_scale), "height scale must be a positive number, not -1")) << refusal(path, no_scale);
}

TEST(HeightGrid, RangeAndCountOfAGridBuiltInMemory) {
  HeightGrid g;
  g.nx = 2;
  g.ny = 2;
  g.z = {NAN, -3.5f, 7.0f, NAN};
  EXPECT_EQ(g.data_count(), 2u);
  EXPECT_EQ(g.height_range(), std::make_pair(-3.5f, 7.0f));
  EXPECT_EQ(g.at(0, 1), 7.0f);  // row 1 starts at index nx
  EXPECT_FALSE(g.has_data(1, 1));
  g.z.assign(4, NAN);
  EXPECT_EQ(g.data_count(), 0u);
  EXPECT_THROW(g.height_range(), InputError);
}

}  // namespace
}  // namespace meshstep
