// meshstep terrain --tile and meshstep terrain-join, as a user runs them: the tile files and
// their names, a tile run alone equal byte for byte to the same tile of the whole run, the
// join without cracks, and every bad tile option and bad grid refused, leaving no file.
#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "meshstep/io/surface_io.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using testing::run_meshstep;
using testing::slurp;
using testing::TempDir;
using testing::stats_line;
const auto& field = testing::json_field;

// A 41 x 33 grid of rough hills, NODATA on a tile border and at a tile corner for N = 9
// (shared lines at 8, 16, 24, 32).
std::string write_tile_hills(const TempDir& dir, const std::string& name = "hills.asc", int rows = 33) {
  std::string text = "ncols 41\nnrows " + std::to_string(rows) + "\nxllcorner 0\nyllcorner 0\ncellsize 5\nNODATA_value -9999\n";
  for (int r = 0; r < rows; ++r) {
    const int j = rows - 1 - r;
    for (int i = 0; i < 41; ++i) {
      const bool hole = (j == 16 && i >= 3 && i <= 6) || (i == 16 && j == 16) || (i == 24 && j >= 9 && j <= 12);
      char v[32];
      std::snprintf(v, sizeof v, "%.3f ",
                    hole ? -9999.0 : 50 + 10 * std::sin(i * 0.3) * std::cos(j * 0.25) + 2 * std::sin(i * j * 0.05));
      text += v;
    }
    text += '\n';
  }
  return dir.write(name, text);
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The tile files of out.EXT for a 41 x 33 grid in tiles of 9: 4 rows x 5 columns.
std::string tile_files(const TempDir& dir, const std::string& ext) {
  std::string files;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 5; ++c) {
      files += ' ';  // appended piece by piece: GCC 12 warns falsely about " " + string + ...
      files += dir.file("out.r" + std::to_string(r) + "-c" + std::to_string(c) + ext);
    }
  return files;
}

TEST(TerrainTilesCli, TilesAreWrittenNamedAndJoinedWithoutCracks) {
  TempDir dir;
  const std::string grid = write_tile_hills(dir);
  for (const std::string ext : {".obj", ".off", ".ply"}) {
    const auto r = run_meshstep("terrain " + grid + " --tile 9 --max-error 0.2 --stats json -o " + dir.file("out" + ext),
                                dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string json = stats_line(r.out);
    EXPECT_EQ(field(json, "tiles"), "20");
    EXPECT_EQ(field(json, "tile_rows"), "4");
    EXPECT_EQ(field(json, "tile_columns"), "5");
    EXPECT_LE(std::stod(field(json, "max_error")), 0.2);
    std::size_t triangles = 0;
    for (int r2 = 0; r2 < 4; ++r2)
      for (int c = 0; c < 5; ++c) {
        const std::string path = dir.file("out.r" + std::to_string(r2) + "-c" + std::to_string(c) + ext);
        ASSERT_TRUE(std::filesystem::exists(path)) << path;
        const io::Surface s = io::read_surface(path);
        triangles += s.triangles.size();
        // In the grid's metres: tile r,c starts at column 8c, row 8r, 5 m apart.
        double x0 = INFINITY, y0 = INFINITY;
        for (const auto& p : s.vertices) {
          x0 = std::min(x0, p.x);
          y0 = std::min(y0, p.y);
        }
        EXPECT_EQ(x0, 8 * c * 5.0);
        EXPECT_EQ(y0, 8 * r2 * 5.0);
      }
    EXPECT_EQ(std::to_string(triangles), field(json, "triangles"));

    const auto j = run_meshstep("terrain-join" + tile_files(dir, ext) + " --stats json -o " + dir.file("joined" + ext),
                                dir.path());
    ASSERT_EQ(j.status, 0) << j.err << j.out;
    const std::string joined = stats_line(j.out);
    EXPECT_EQ(field(joined, "cracks"), "0");
    EXPECT_EQ(field(joined, "boundary_loops"), "1");
    EXPECT_EQ(field(joined, "ok"), "true");
    EXPECT_EQ(field(joined, "triangles"), field(json, "triangles"));
    EXPECT_EQ(field(joined, "vertices"), field(json, "vertices")) << "each vertex counted once by the tiled run";
    EXPECT_EQ(std::stod(field(joined, "area")), 40 * 5.0 * 32 * 5.0);
    const io::SurfaceReport report = io::report_surface(io::read_surface(dir.file("joined" + ext)));
    EXPECT_TRUE(report.clean()) << io::describe(report);
    EXPECT_EQ(report.boundary_loops, 1u);
  }
}

TEST(TerrainTilesCli, ATileRunAloneIsByteForByteTheTileOfTheWholeRun) {
  TempDir dir;
  const std::string grid = write_tile_hills(dir);
  const auto no_folder = run_meshstep("terrain " + grid + " --tile 9 --max-error 1% -q -o " + dir.file("all/out.ply"), dir.path());
  EXPECT_EQ(no_folder.status, 1);
  EXPECT_TRUE(has(no_folder.err, "does not exist")) << no_folder.err;
  std::filesystem::create_directory(dir.path() / "all");
  std::filesystem::create_directory(dir.path() / "one");
  ASSERT_EQ(run_meshstep("terrain " + grid + " --tile 9 --max-error 1% -q -o " + dir.file("all/out.ply"), dir.path())
                .status,
            0);
  for (const std::string index : {"0,0", "2,2", "3,4", "1,3"}) {
    const auto r = run_meshstep("terrain " + grid + " --tile 9 --tile-index " + index + " --max-error 1% -o " +
                                    dir.file("one/out.ply"),
                                dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string name = "out.r" + index.substr(0, 1) + "-c" + index.substr(2) + ".ply";
    const std::string alone = slurp(dir.path() / "one" / name);
    EXPECT_FALSE(alone.empty()) << name;
    EXPECT_EQ(alone, slurp(dir.path() / "all" / name)) << name;
  }
  // Only the tiles asked for were written, and no staged file is left.
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir.path() / "one")) names.push_back(e.path().filename());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"out.r0-c0.ply", "out.r1-c3.ply", "out.r2-c2.ply", "out.r3-c4.ply"}));
}

TEST(TerrainTilesCli, APercentBoundIsTheWholeGridsAndTheTilesMeetIt) {
  TempDir dir;
  const std::string grid = write_tile_hills(dir);
  const auto whole = run_meshstep("terrain " + grid + " --max-error 0.5% -q --stats json", dir.path());
  const auto tiled = run_meshstep("terrain " + grid + " --tile 9 --max-error 0.5% -q --stats json", dir.path());
  ASSERT_EQ(whole.status, 0) << whole.err;
  ASSERT_EQ(tiled.status, 0) << tiled.err;
  EXPECT_EQ(field(stats_line(whole.out), "bound"), field(stats_line(tiled.out), "bound"));
  EXPECT_LE(std::stod(field(stats_line(tiled.out), "max_error")), std::stod(field(stats_line(tiled.out), "bound")));
  // The tile larger than the grid: one tile.
  const auto one = run_meshstep("terrain " + grid + " --tile 1000 --max-error 0.5% -q --stats json", dir.path());
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(field(stats_line(one.out), "tiles"), "1");
}

TEST(TerrainTilesCli, APngHeightmapIsTiledToo) {
  TempDir dir;
  std::vector<unsigned char> grey(30 * 20);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 30; ++x) grey[y * 30 + x] = static_cast<unsigned char>(128 + 100 * std::sin(x * 0.3 + y * 0.2));
  const std::string png = dir.file("h.png");
  ASSERT_NE(stbi_write_png(png.c_str(), 30, 20, 1, grey.data(), 30), 0);
  const auto r = run_meshstep("terrain " + png + " --tile 8 --z-scale 50 --max-error 0.5 -q -o " + dir.file("p.obj"),
                              dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  std::string files;
  for (int t = 0; t < 3; ++t)
    for (int c = 0; c < 5; ++c) {
      files += ' ';
      files += dir.file("p.r" + std::to_string(t) + "-c" + std::to_string(c) + ".obj");
    }
  const auto j = run_meshstep("terrain-join" + files + " -q --stats json", dir.path());
  EXPECT_EQ(j.status, 0) << j.err;
  EXPECT_EQ(field(stats_line(j.out), "ok"), "true");
}

TEST(TerrainTilesCli, TheJoinRefusesTilesThatDoNotMeet) {
  TempDir dir;
  const std::string grid = write_tile_hills(dir);
  ASSERT_EQ(run_meshstep("terrain " + grid + " --tile 9 --max-error 0.2 -q -o " + dir.file("out.obj"), dir.path()).status, 0);
  // A tile made with another bound: its borders differ from its neighbours'.
  ASSERT_EQ(run_meshstep("terrain " + grid + " --tile 9 --tile-index 1,1 --max-error 2 -q -o " + dir.file("out.obj"),
                         dir.path())
                .status,
            0);
  const auto cracked = run_meshstep("terrain-join" + tile_files(dir, ".obj") + " --stats json -o " + dir.file("j.obj"),
                                    dir.path());
  EXPECT_EQ(cracked.status, 1);
  EXPECT_TRUE(has(cracked.err, "crack")) << cracked.err;
  EXPECT_NE(field(stats_line(cracked.out), "cracks"), "0");
  EXPECT_FALSE(std::filesystem::exists(dir.file("j.obj")));
  // A tile missing: the rectangle has a hole.
  const std::string files = tile_files(dir, ".obj");
  const auto holed = run_meshstep("terrain-join" + files.substr(0, files.rfind(' ')) + " -q", dir.path());
  EXPECT_EQ(holed.status, 1);
  const auto missing = run_meshstep("terrain-join " + dir.file("nope.obj"), dir.path());
  EXPECT_EQ(missing.status, 1);
}

TEST(TerrainTilesCli, HelpAndListTellOfTiles) {
  TempDir dir;
  const auto help = run_meshstep("--help", dir.path());
  EXPECT_TRUE(has(help.out, "terrain-join")) << help.out;
  const auto terrain_help = run_meshstep("terrain --help", dir.path());
  for (const char* words : {"--tile", "--tile-index", "OUT.rR-cC.EXT", "4 x N x COLUMNS bytes"})
    EXPECT_TRUE(has(terrain_help.out, words)) << words << " in " << terrain_help.out;
  const auto list = run_meshstep("list", dir.path());
  EXPECT_TRUE(has(list.out, "terrain-join")) << list.out;
  EXPECT_TRUE(has(list.out, "terrain --tile N")) << list.out;
  const auto json = run_meshstep("list --json", dir.path());
  EXPECT_TRUE(has(json.out, "\"terrain_tiles\":[")) << json.out;
}

TEST(TerrainTilesCli, BadTileOptionsAreRefused) {
  TempDir dir;
  const std::string grid = write_tile_hills(dir);
  const auto refused = [&](const std::string& options, int status, const std::string& words) {
    const auto r = run_meshstep("terrain " + grid + " --max-error 1 " + options + " -o " + dir.file("x.obj"), dir.path());
    EXPECT_EQ(r.status, status) << options << ": " << r.err;
    EXPECT_TRUE(has(r.err, words)) << options << ": " << r.err;
  };
  refused("--tile 1", 2, "at least 2 x 2 samples");
  refused("--tile 0", 2, "at least 2 x 2 samples");
  refused("--tile -4", 2, "at least 2 x 2 samples");
  refused("--tile-index 0,0", 2, "--tile-index needs --tile");
  refused("--tile 9 --tile-index 3", 2, "is not ROW,COLUMN");
  refused("--tile 9 --tile-index a,1", 2, "is not ROW,COLUMN");
  refused("--tile 9 --tile-index 1,-1", 2, "is not ROW,COLUMN");
  refused("--tile 9 --tile-index 4,0", 1, "tile 4,0 is outside the grid");
  refused("--tile 9 --tile-index 0,5", 1, "4 rows x 5 columns of tiles");
  refused("--tile 9 --base 5", 2, "--base");
  const auto cap_alone = run_meshstep("terrain " + grid + " --tile 9 --max-triangles 100", dir.path());
  EXPECT_EQ(cap_alone.status, 2);
  EXPECT_TRUE(has(cap_alone.err, "--tile needs --max-error")) << cap_alone.err;
  const auto stl = run_meshstep("terrain " + grid + " --max-error 1 --tile 9 -o " + dir.file("x.stl"), dir.path());
  EXPECT_EQ(stl.status, 2);
  EXPECT_TRUE(has(stl.err, ".obj, .off or .ply")) << stl.err;
  // Nothing was written by any of them.
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"hills.asc", "stderr.txt", "stdout.txt"}));
}

TEST(TerrainTilesCli, ABadGridIsRefusedWithItsLineAndLeavesNoTile) {
  TempDir dir;
  // 33 rows declared, 30 written: the northern tiles are done before the end is found short.
  const std::string full = slurp(write_tile_hills(dir, "full.asc"));
  std::filesystem::remove(dir.path() / "full.asc");
  std::string cut = full;
  for (int k = 0; k < 3; ++k) cut = cut.substr(0, cut.rfind('\n', cut.size() - 2) + 1);
  const std::string truncated = dir.write("cut.asc", cut);
  std::string bad = full;
  const std::size_t last_row = bad.rfind('\n', bad.size() - 2) + 1;
  ASSERT_EQ(bad.compare(last_row, 3, "50."), 0);
  bad[last_row + 1] = 'x';  // a bad value in the last row: "5x.000"
  const std::string bad_value = dir.write("bad.asc", bad);
  for (const std::string& grid : {truncated, bad_value})
    for (const std::string extra : {"", " --tile-index 3,0", " --in-percent"}) {
      const std::string bound = extra == " --in-percent" ? " --max-error 1%" : " --max-error 0.2" + extra;
      const auto r = run_meshstep("terrain " + grid + " --tile 9" + bound + " -v -o " + dir.file("out.ply"), dir.path());
      EXPECT_EQ(r.status, 1) << grid << extra;
      EXPECT_TRUE(has(r.err, grid + ":")) << r.err;
      const std::string line = r.err.substr(r.err.find(grid + ":") + grid.size() + 1);
      EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(line[0]))) << "no line number: " << r.err;
      if (extra.empty()) {
        EXPECT_TRUE(has(r.err, "tile 3,0")) << "a tile was made before the problem: " << r.err;
      }
      EXPECT_EQ(dir.entries(), (std::vector<std::string>{"bad.asc", "cut.asc", "stderr.txt", "stdout.txt"}))
          << grid << extra;
    }
}

}  // namespace
}  // namespace meshstep
