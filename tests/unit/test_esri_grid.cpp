// ESRI ASCII grids: the header, cell lookup (rows run north to south), no-data cells, and
// the shared terrain grids read whole.
#include <gtest/gtest.h>

#include <filesystem>
#include <span>
#include <string>
#include <utility>

#include "meshstep/error.hpp"
#include "meshstep/io/esri_grid.hpp"
#include "temp_dir.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

TEST(EsriGrid, CellsRunNorthToSouthAndNoDataIsNoValue) {
  testing::TempDir dir("meshstep_esri_");
  const std::string path = dir.write("g.asc",
                                     "NCOLS 3\nnrows 2\nxllcenter 10.5\nyllcenter 20.5\ncellsize 1\n"
                                     "nodata_value -1\n1 2 3\n4 -1 6\n");
  const io::EsriGrid g = io::read_esri_grid(path);
  EXPECT_EQ(g.ncols, 3u);
  EXPECT_EQ(g.nrows, 2u);
  EXPECT_EQ(g.x0, 10.0);  // centers given: the corner is half a cell lower-left
  EXPECT_EQ(g.y0, 20.0);
  EXPECT_EQ(g.at({10.5, 21.5}, 0.0), 1.0);  // north-west cell: first value
  EXPECT_EQ(g.at({10.5, 20.5}, 0.0), 4.0);  // south-west
  EXPECT_EQ(g.at({12.9, 20.1}, 0.0), 6.0);
  EXPECT_EQ(g.at({13.0, 22.0}, 0.0), 3.0);  // the upper-right corner belongs to the last cell
  EXPECT_EQ(g.at({11.5, 20.5}, 0.0), 0.0);  // no data
  EXPECT_EQ(g.at({9.9, 20.5}, 0.0), 0.0);   // outside
}

TEST(EsriGrid, MalformedFilesNameTheLine) {
  testing::TempDir dir("meshstep_esri_");
  const auto message = [&](const std::string& text) {
    try {
      io::read_esri_grid(dir.write("bad.asc", text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\n1 2\n").find("no cellsize"), std::string::npos);
  EXPECT_NE(message("ncols 2\nncols 2\n").find("bad.asc:2: 'ncols' appears twice"), std::string::npos);
  EXPECT_NE(message("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 0\n1 2\n").find("cellsize must be positive"),
            std::string::npos);
  EXPECT_NE(message("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n").find("more values"),
            std::string::npos);
}

// Issue 31, fault 1: ncols x nrows was multiplied in 64 bits and wrapped: 2^32 x 2^32 read
// as a grid of 0 values and (2^62 + 1) x 4 as one of 4, "filled" by the file, and a lookup
// then read far past them. The product is checked without wrapping, and against what the
// file's bytes can hold, at the later count's line, by both ways of reading a grid.
TEST(EsriGrid, CountsWhoseProductWrapsOrPassesTheFileAreRefusedAtTheirLine) {
  testing::TempDir dir("meshstep_esri_");
  const std::string corner = "xllcorner 0\nyllcorner 0\ncellsize 1\n";
  const std::pair<std::string, std::string> cases[] = {
      {"ncols 4294967296\nnrows 4294967296\n" + corner, "bad.asc:2: 4294967296 x 4294967296 samples is too large a grid"},
      {"nrows 4\nncols 4611686018427387905\n" + corner + "1 2 3 4\n",
       "bad.asc:2: 4611686018427387905 x 4 samples is too large a grid"},
      {"ncols 1000\nnrows 1000\n" + corner + "1 2 3\n4 5 6\n",
       "bad.asc:2: 1000 x 1000 = 1000000 values, but the file can hold at most 6"}};
  for (const auto& [text, expected] : cases) {
    const std::string path = dir.write("bad.asc", text);
    for (const bool by_rows : {false, true}) {
      std::string message = "no error";
      try {
        if (by_rows)
          io::read_esri_grid_rows(path, [](const io::EsriGrid&, std::size_t, std::span<const double>, std::size_t) {});
        else
          io::read_esri_grid(path);
      } catch (const InputError& e) {
        message = e.what();
      }
      EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
  }
}

TEST(EsriGrid, SharedTerrainGridsReadWhole) {
  for (const char* name : {"volcano.asc", "jacksboro_fault.asc"}) {
    const std::filesystem::path path = testing::shared_data() / "terrain" / name;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent: skipped";
    const io::EsriGrid g = io::read_esri_grid(path.string());
    EXPECT_EQ(g.values.size(), g.ncols * g.nrows) << name;
    EXPECT_GT(g.cellsize, 0.0);
  }
}

}  // namespace
}  // namespace meshstep
