// Tiled terrain (terrain/tiles.hpp, terrain/tile_join.hpp): neighbouring tiles have the same
// border vertices and edges along their shared line, every sample is within the bound in
// its tile (checked here by a measure of the tests' own), the tiles join into one surface
// without cracks over the whole rectangle, a tile made alone is the tile of the whole run,
// and samples without data on borders and corners are handled the same by every tile.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <random>
#include <set>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tile_join.hpp"
#include "meshstep/terrain/tiles.hpp"
#include "meshstep/terrain/tin.hpp"
#include "meshstep/terrain/tin_surface.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep::terrain {
namespace {

// Rough hills: a few long waves and some short ones, so that every tile needs vertices.
HeightGrid rough_hills(std::size_t nx, std::size_t ny, unsigned seed, double dx = 10.0, double dy = 8.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double fx[6], fy[6], ph[6], amp[6];
  for (int k = 0; k < 6; ++k) {
    fx[k] = 0.01 + 0.4 * u(rng);
    fy[k] = 0.01 + 0.4 * u(rng);
    ph[k] = 6.28 * u(rng);
    amp[k] = 1.0 + 10.0 * u(rng);
  }
  HeightGrid g;
  g.nx = nx;
  g.ny = ny;
  g.dx = dx;
  g.dy = dy;
  g.z.resize(nx * ny);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      double z = 500.0;
      for (int k = 0; k < 6; ++k) z += amp[k] * std::sin(fx[k] * i + ph[k]) * std::cos(fy[k] * j + ph[k]);
      g.z[i + j * nx] = static_cast<float>(z);
    }
  return g;
}

struct MadeTile {
  Tile tile;
  Tin tin;
};

std::vector<MadeTile> make_tiles(const HeightGrid& g, std::size_t n, double bound,
                                 TerrainAlgorithm algorithm = TerrainAlgorithm::lepp_surface,
                                 std::optional<TileIndex> only = std::nullopt) {
  std::vector<MadeTile> tiles;
  cut_tiles(g, n, only, [&](const Tile& t) {
    tiles.push_back({t, approximate_tile(t, {.algorithm = algorithm, .max_error = bound})});
  });
  return tiles;
}

const MadeTile& find_tile(const std::vector<MadeTile>& tiles, TileIndex index) {
  for (const auto& t : tiles)
    if (t.tile.index == index) return t;
  throw std::runtime_error("no such tile");
}

// A vertex by the whole grid's sample indices, with its height.
struct GlobalVertex {
  std::size_t i, j;
  float height;
  auto operator<=>(const GlobalVertex&) const = default;
};

GlobalVertex global_vertex(const MadeTile& t, std::uint32_t v) {
  return {t.tile.i0 + t.tin.samples[v] % t.tile.grid.nx, t.tile.j0 + t.tin.samples[v] / t.tile.grid.nx,
          t.tin.heights[v]};
}

// The vertices of a tile on the grid line i = column (or j = row), and its edges along it,
// by the vertices' global indices.
struct LineView {
  std::vector<GlobalVertex> vertices;                              // sorted
  std::set<std::pair<GlobalVertex, GlobalVertex>> edges;  // (smaller, larger)
};

LineView on_line(const MadeTile& t, std::optional<std::size_t> column, std::optional<std::size_t> row) {
  const auto on = [&](const GlobalVertex& g) { return column ? g.i == *column : g.j == *row; };
  LineView view;
  for (std::uint32_t v = 0; v < t.tin.samples.size(); ++v)
    if (on(global_vertex(t, v))) view.vertices.push_back(global_vertex(t, v));
  std::sort(view.vertices.begin(), view.vertices.end());
  for (const auto& tri : t.tin.triangles)
    for (int k = 0; k < 3; ++k) {
      const GlobalVertex a = global_vertex(t, tri[k]), b = global_vertex(t, tri[(k + 1) % 3]);
      if (on(a) && on(b)) view.edges.insert(std::minmax(a, b));
    }
  return view;
}

// Every pair of neighbours: the same vertices on the shared line, and the same edges along
// it, which chain those vertices one after the other (so no vertex of one is missing from
// the other's edges: no T-junction, no crack).
void expect_neighbours_agree(const std::vector<MadeTile>& tiles, const TileLayout& layout) {
  std::size_t lines = 0;
  for (const auto& a : tiles)
    for (const auto& b : tiles) {
      const bool east = b.tile.index == TileIndex{a.tile.index.row, a.tile.index.column + 1};
      const bool north = b.tile.index == TileIndex{a.tile.index.row + 1, a.tile.index.column};
      if (!east && !north) continue;
      ++lines;
      const std::optional<std::size_t> column = east ? std::optional(b.tile.i0) : std::nullopt;
      const std::optional<std::size_t> row = north ? std::optional(b.tile.j0) : std::nullopt;
      const LineView va = on_line(a, column, row), vb = on_line(b, column, row);
      ASSERT_EQ(va.vertices, vb.vertices) << "tiles " << a.tile.index.row << "," << a.tile.index.column << " and "
                                          << b.tile.index.row << "," << b.tile.index.column;
      ASSERT_EQ(va.edges, vb.edges);
      ASSERT_GE(va.vertices.size(), 2u);
      ASSERT_EQ(va.edges.size(), va.vertices.size() - 1);
      for (std::size_t k = 0; k + 1 < va.vertices.size(); ++k)
        EXPECT_TRUE(va.edges.count({va.vertices[k], va.vertices[k + 1]})) << "the chain skips a vertex";
    }
  EXPECT_EQ(lines, layout.rows() * (layout.columns() - 1) + layout.columns() * (layout.rows() - 1));
}

// The tests' own measure of a tile, in metres and floating-point barycentrics: the largest
// error over the samples with data, and how many samples with data no triangle covers.
struct OwnCheck {
  double max_error = 0.0;
  std::size_t uncovered = 0;
};

OwnCheck check_tile_independently(const MadeTile& t) {
  const HeightGrid& g = t.tile.grid;
  std::vector<double> error(g.nx * g.ny, -1.0);
  for (const auto& tri : t.tin.triangles) {
    double x[3], y[3], z[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = static_cast<double>(t.tin.samples[tri[k]] % g.nx) * g.dx;
      y[k] = static_cast<double>(t.tin.samples[tri[k]] / g.nx) * g.dy;
      z[k] = t.tin.heights[tri[k]];
    }
    const double det = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    const auto lo_i = static_cast<std::size_t>(std::round(std::min({x[0], x[1], x[2]}) / g.dx));
    const auto hi_i = static_cast<std::size_t>(std::round(std::max({x[0], x[1], x[2]}) / g.dx));
    const auto lo_j = static_cast<std::size_t>(std::round(std::min({y[0], y[1], y[2]}) / g.dy));
    const auto hi_j = static_cast<std::size_t>(std::round(std::max({y[0], y[1], y[2]}) / g.dy));
    for (std::size_t j = lo_j; j <= hi_j; ++j)
      for (std::size_t i = lo_i; i <= hi_i; ++i) {
        const double px = static_cast<double>(i) * g.dx, py = static_cast<double>(j) * g.dy;
        const double l1 = ((px - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (py - y[0])) / det;
        const double l2 = ((x[1] - x[0]) * (py - y[0]) - (px - x[0]) * (y[1] - y[0])) / det;
        const double l0 = 1.0 - l1 - l2;
        if (l0 < -1e-12 || l1 < -1e-12 || l2 < -1e-12) continue;
        const std::size_t s = i + j * g.nx;
        if (!g.has_data(i, j)) continue;
        error[s] = std::max(error[s], std::abs(g.z[s] - (l0 * z[0] + l1 * z[1] + l2 * z[2])));
      }
  }
  OwnCheck c;
  for (std::size_t s = 0; s < error.size(); ++s) {
    if (std::isnan(g.z[s])) continue;
    if (error[s] < 0.0) ++c.uncovered;
    c.max_error = std::max(c.max_error, error[s]);
  }
  return c;
}

void expect_within_bound(const std::vector<MadeTile>& tiles, double bound) {
  for (const auto& t : tiles) {
    const OwnCheck own = check_tile_independently(t);
    EXPECT_EQ(own.uncovered, 0u);
    EXPECT_LE(own.max_error, bound * (1 + 1e-9) + 1e-9) << "tile " << t.tile.index.row << "," << t.tile.index.column;
    const ErrorMeasure measured = measure_error(t.tile.grid, t.tin);  // the library's, which the CLI applies
    EXPECT_EQ(measured.uncovered, 0u);
    EXPECT_LE(measured.max, bound);
  }
}

io::Surface join(const std::vector<MadeTile>& tiles, std::size_t* welded = nullptr) {
  SurfaceWelder welder;
  for (const auto& t : tiles) welder.add(tile_surface(t.tile, t.tin));
  if (welded) *welded = welder.welded();
  return welder.take();
}

// --- The layout ---------------------------------------------------------------------------

TEST(TerrainTiles, TheLayoutSharesOneSampleBetweenNeighbours) {
  const TileLayout even{37, 28, 10};  // 36 = 4 x 9 columns, 27 = 3 x 9 rows
  EXPECT_EQ(even.columns(), 4u);
  EXPECT_EQ(even.rows(), 3u);
  EXPECT_EQ(even.first_column(1), 9u);
  EXPECT_EQ(even.last_column(0), 9u);
  EXPECT_EQ(even.last_column(3), 36u);
  const TileLayout odd{38, 30, 10};  // one column and two rows past the last full tiles
  EXPECT_EQ(odd.columns(), 5u);
  EXPECT_EQ(odd.first_column(4), 36u);
  EXPECT_EQ(odd.last_column(4), 37u);
  EXPECT_EQ(odd.rows(), 4u);
  EXPECT_EQ(odd.last_row(3), 29u);
  const TileLayout pairs{5, 3, 2};
  EXPECT_EQ(pairs.columns(), 4u);
  EXPECT_EQ(pairs.rows(), 2u);
  const TileLayout whole{20, 10, 50};
  EXPECT_EQ(whole.columns(), 1u);
  EXPECT_EQ(whole.rows(), 1u);
  EXPECT_EQ(whole.last_column(0), 19u);
}

// --- One side in 1D -----------------------------------------------------------------------

TEST(TerrainTiles, ASideKeepsWhatItNeedsAndNoSampleWithoutData) {
  std::vector<float> side(200);
  for (std::size_t k = 0; k < side.size(); ++k) side[k] = static_cast<float>(100 + 20 * std::sin(k * 0.11) + 0.3 * k);
  for (std::size_t k = 60; k < 75; ++k) side[k] = NAN;
  for (const double bound : {5.0, 1.0, 0.1, 0.0}) {
    const std::vector<std::size_t> kept = simplify_profile(side, side.front(), side.back(), bound);
    EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
    std::vector<std::size_t> vertices{0};
    for (const std::size_t k : kept) {
      EXPECT_GT(k, 0u);
      EXPECT_LT(k, side.size() - 1);
      EXPECT_FALSE(std::isnan(side[k])) << "a sample without data kept";
      vertices.push_back(k);
    }
    vertices.push_back(side.size() - 1);
    // Every sample with data within the bound of its chord.
    for (std::size_t v = 0; v + 1 < vertices.size(); ++v) {
      const std::size_t a = vertices[v], b = vertices[v + 1];
      for (std::size_t k = a; k <= b; ++k) {
        if (std::isnan(side[k])) continue;
        const double t = static_cast<double>(k - a) / static_cast<double>(b - a);
        EXPECT_LE(std::abs(side[k] - (side[a] * (1 - t) + side[b] * t)), bound + 1e-9) << k;
      }
    }
    if (bound == 0.0) {
      EXPECT_GT(kept.size(), 150u);
    }
  }
  // A straight side keeps nothing; the same side gives the same answer every time.
  std::vector<float> straight(50);
  for (std::size_t k = 0; k < straight.size(); ++k) straight[k] = static_cast<float>(k) * 0.5f;
  EXPECT_TRUE(simplify_profile(straight, straight.front(), straight.back(), 0.01).empty());
  EXPECT_EQ(simplify_profile(side, side.front(), side.back(), 0.7), simplify_profile(side, side.front(), side.back(), 0.7));
}

TEST(TerrainTiles, ACornerWithoutDataFollowsItsRowThenTheNorth) {
  const float n = NAN;
  const std::vector<float> row{n, 4, n, n, n, 7, n};
  const std::vector<float> north{1, 2, 3, n, 5, n, n};
  EXPECT_EQ(tile_corner_height(row, north, 1), 4.0f);  // its own
  EXPECT_EQ(tile_corner_height(row, north, 3), 4.0f);  // nearest on the row, ties to the west
  EXPECT_EQ(tile_corner_height(row, north, 6), 7.0f);
  const std::vector<float> empty(7, n);
  EXPECT_EQ(tile_corner_height(empty, north, 4), 5.0f);  // the row has no data: north, its column
  EXPECT_EQ(tile_corner_height(empty, north, 6), 5.0f);  // north, the nearest column
  EXPECT_EQ(tile_corner_height(empty, north, 3), 3.0f);  // ties (columns 2 and 4) to the west
  EXPECT_EQ(tile_corner_height(empty, empty, 3), 0.0f);  // nothing anywhere
}

// --- Tiles in memory ----------------------------------------------------------------------

TEST(TerrainTiles, NeighboursShareTheirBorderAndEverySampleIsWithinTheBound) {
  const HeightGrid g = rough_hills(61, 47, 1);  // 60 = 6 x 10 columns, 46 not a multiple of 10
  const TileLayout layout{g.nx, g.ny, 11};
  for (const auto algorithm : {TerrainAlgorithm::lepp_surface, TerrainAlgorithm::greedy})
    for (const double bound : {2.0, 0.3}) {
      const std::vector<MadeTile> tiles = make_tiles(g, 11, bound, algorithm);
      ASSERT_EQ(tiles.size(), layout.rows() * layout.columns());
      expect_neighbours_agree(tiles, layout);
      expect_within_bound(tiles, bound);
    }
}

TEST(TerrainTiles, ATileNeverInsertsOnItsRectangleBeyondItsBorder) {
  const HeightGrid g = rough_hills(40, 40, 2);
  for (const auto& t : make_tiles(g, 15, 0.2)) {
    const BorderVertices border = tile_border(t.tile, 0.2);
    std::set<std::uint32_t> expected(border.samples.begin(), border.samples.end()), found;
    const std::size_t nx = t.tile.grid.nx, ny = t.tile.grid.ny;
    for (const std::uint32_t s : t.tin.samples) {
      const std::size_t i = s % nx, j = s / nx;
      if (i == 0 || j == 0 || i == nx - 1 || j == ny - 1) found.insert(s);
    }
    EXPECT_EQ(found, expected);
    EXPECT_GT(t.tin.samples.size(), border.samples.size()) << "the inside was refined too";
  }
}

TEST(TerrainTiles, TheTilesJoinWithoutCracksOverTheWholeRectangle) {
  const HeightGrid g = rough_hills(53, 38, 3);
  const std::vector<MadeTile> tiles = make_tiles(g, 9, 0.5);
  std::size_t welded = 0;
  const io::Surface joined = join(tiles, &welded);
  const TileJoinCheck check = check_joined_tiles(joined);
  EXPECT_TRUE(check.ok()) << describe(check);
  EXPECT_EQ(check.surface.boundary_loops, 1u);
  EXPECT_EQ(check.cracks, 0u);
  EXPECT_EQ(check.surface.non_manifold_edges, 0u);
  const double rectangle = static_cast<double>(g.nx - 1) * g.dx * static_cast<double>(g.ny - 1) * g.dy;
  EXPECT_NEAR(check.area, rectangle, 1e-9 * rectangle);
  EXPECT_NEAR(check.rectangle_area, rectangle, 1e-9 * rectangle);
  EXPECT_GT(welded, 0u);
  // Every vertex at the whole grid's own position of its sample, exactly.
  for (const auto& p : joined.vertices) {
    const double i = std::round(p.x / g.dx), j = std::round(p.y / g.dy);
    EXPECT_EQ(p.x, i * g.dx);
    EXPECT_EQ(p.y, j * g.dy);
    EXPECT_EQ(static_cast<float>(p.z), g.at(static_cast<std::size_t>(i), static_cast<std::size_t>(j)));
  }
}

TEST(TerrainTiles, TheJoinCheckFindsTheCracksOfTilesMadeApart) {
  const HeightGrid g = rough_hills(41, 41, 4);
  // Each tile approximated alone, as a grid of its own: its sides go their own way.
  std::vector<MadeTile> apart;
  cut_tiles(g, 21, std::nullopt, [&](const Tile& t) { apart.push_back({t, approximate(t.grid, {.max_error = 0.3})}); });
  const TileJoinCheck cracked = check_joined_tiles(join(apart));
  EXPECT_FALSE(cracked.ok());
  EXPECT_GT(cracked.cracks, 0u) << describe(cracked);
  // One tile of a run made with another bound: its border differs from its neighbours'.
  std::vector<MadeTile> tiles = make_tiles(g, 21, 0.3);
  tiles[0].tin = approximate_tile(tiles[0].tile, {.max_error = 3.0});
  EXPECT_GT(check_joined_tiles(join(tiles)).cracks, 0u);
  // A tile missing: a hole, not a disc over the rectangle.
  tiles = make_tiles(g, 15, 0.3);
  tiles.erase(tiles.begin() + 4);
  EXPECT_FALSE(check_joined_tiles(join(tiles)).ok());
}

TEST(TerrainTiles, ATileMadeAloneIsTheTileOfTheWholeRun) {
  HeightGrid g = rough_hills(50, 44, 5);
  g.z[20 + 20 * g.nx] = NAN;  // a corner of tile 1,1 and of three others (N = 11: lines 10, 20, 30, 40)
  const std::vector<MadeTile> all = make_tiles(g, 11, 0.4);
  for (const TileIndex index : {TileIndex{0, 0}, TileIndex{1, 1}, TileIndex{2, 4}, TileIndex{4, 3}}) {
    const std::vector<MadeTile> alone = make_tiles(g, 11, 0.4, TerrainAlgorithm::lepp_surface, index);
    ASSERT_EQ(alone.size(), 1u);
    const MadeTile& a = alone[0];
    const MadeTile& b = find_tile(all, index);
    EXPECT_EQ(a.tile.i0, b.tile.i0);
    EXPECT_EQ(a.tile.j0, b.tile.j0);
    EXPECT_EQ(a.tile.corner_heights, b.tile.corner_heights);
    ASSERT_EQ(a.tile.grid.z.size(), b.tile.grid.z.size());
    EXPECT_EQ(0, std::memcmp(a.tile.grid.z.data(), b.tile.grid.z.data(), a.tile.grid.z.size() * sizeof(float)));
    EXPECT_EQ(a.tin.samples, b.tin.samples);
    EXPECT_EQ(a.tin.triangles, b.tin.triangles);
  }
  EXPECT_THROW(make_tiles(g, 11, 0.4, TerrainAlgorithm::lepp_surface, TileIndex{5, 0}), InputError);
  EXPECT_THROW(make_tiles(g, 11, 0.4, TerrainAlgorithm::lepp_surface, TileIndex{0, 5}), InputError);
}

TEST(TerrainTiles, SmallAndOddLayouts) {
  const HeightGrid g = rough_hills(23, 17, 6);
  // One tile: larger than the grid.
  const std::vector<MadeTile> one = make_tiles(g, 100, 0.3);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].tile.grid.nx, g.nx);
  EXPECT_EQ(one[0].tile.grid.ny, g.ny);
  expect_within_bound(one, 0.3);
  const io::Surface s = tile_surface(one[0].tile, one[0].tin);
  const io::Surface whole = to_surface(g, one[0].tin);  // the same numbers as an untiled run's
  ASSERT_EQ(s.vertices.size(), whole.vertices.size());
  for (std::size_t v = 0; v < s.vertices.size(); ++v) EXPECT_EQ(s.vertices[v], whole.vertices[v]);
  // 2 x 2 tiles, and tiles of 2 x 2 samples (two triangles each, nothing to choose).
  for (const std::size_t n : {std::size_t{12}, std::size_t{2}, std::size_t{3}, std::size_t{22}}) {
    const std::vector<MadeTile> tiles = make_tiles(g, n, 0.3);
    const TileLayout layout{g.nx, g.ny, n};
    ASSERT_EQ(tiles.size(), layout.rows() * layout.columns()) << n;
    if (n == 12) {
      EXPECT_EQ(tiles.size(), 4u);
    }
    expect_neighbours_agree(tiles, layout);
    expect_within_bound(tiles, 0.3);
    EXPECT_TRUE(check_joined_tiles(join(tiles)).ok()) << n;
    if (n == 2) {
      for (const auto& t : tiles) EXPECT_EQ(t.tin.triangles.size(), 2u);
    }
  }
}

TEST(TerrainTiles, NoDataOnBordersAndCornersIsTheSameForEveryTile) {
  HeightGrid g = rough_hills(45, 45, 7);
  const auto hole = [&](std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1) {
    for (std::size_t j = j0; j <= j1; ++j)
      for (std::size_t i = i0; i <= i1; ++i) g.z[i + j * g.nx] = NAN;
  };
  // N = 12: shared lines at 11, 22, 33.
  hole(5, 8, 11, 11);     // a run along a shared row
  hole(22, 22, 2, 9);     // a run along a shared column
  hole(20, 24, 20, 24);   // a hole round an inner corner (22, 22)
  hole(0, 44, 33, 33);    // a whole shared row without data: its corners look north
  hole(0, 3, 0, 3);       // the grid's own corner
  hole(0, 44, 40, 44);    // the top rows: corners at 44 look along row 44, then north, then 0
  const std::vector<MadeTile> tiles = make_tiles(g, 12, 0.4);
  const TileLayout layout{g.nx, g.ny, 12};
  expect_neighbours_agree(tiles, layout);
  expect_within_bound(tiles, 0.4);
  const TileJoinCheck check = check_joined_tiles(join(tiles));
  EXPECT_TRUE(check.ok()) << describe(check);
  // Every vertex but a corner has data; corners without data took the rules' heights.
  for (const auto& t : tiles) {
    for (std::size_t v = 4; v < t.tin.samples.size(); ++v)
      EXPECT_FALSE(std::isnan(t.tile.grid.z[t.tin.samples[v]]));
    for (const float h : t.tin.heights) EXPECT_FALSE(std::isnan(h));
  }
  const MadeTile& inner = find_tile(tiles, {2, 2});  // south-west corner (22, 22), in the hole
  EXPECT_EQ(inner.tile.corner_heights[0], g.at(19, 22)) << "the nearest on its row, ties to the west";
  const MadeTile& row33 = find_tile(tiles, {3, 1});  // its south side is row 33, all without data
  EXPECT_EQ(row33.tile.corner_heights[0], g.at(11, 34)) << "nothing on the row: the nearest north";
  const MadeTile& top = find_tile(tiles, {3, 3});  // its north side is row 44, the top, without data
  EXPECT_EQ(top.tile.corner_heights[2], 0.0f) << "nothing on or north of the row";
}

TEST(TerrainTiles, TheBorderRulesAreChecked) {
  const HeightGrid g = rough_hills(10, 8, 8);
  BorderVertices border;
  border.samples = {0, 9, 79, 70};
  for (const auto s : border.samples) border.heights.push_back(g.z[s]);
  EXPECT_NO_THROW(approximate_within_border(g, border, {.max_error = 1}));
  BorderVertices swapped = border;
  std::swap(swapped.samples[1], swapped.samples[3]);
  EXPECT_THROW(approximate_within_border(g, swapped, {.max_error = 1}), InputError);
  BorderVertices inside = border;
  inside.samples.push_back(15);  // (5, 1): not on the rectangle
  inside.heights.push_back(1.0f);
  EXPECT_THROW(approximate_within_border(g, inside, {.max_error = 1}), InputError);
  BorderVertices twice = border;
  twice.samples.push_back(9);
  twice.heights.push_back(1.0f);
  EXPECT_THROW(approximate_within_border(g, twice, {.max_error = 1}), InputError);
  BorderVertices no_height = border;
  no_height.heights[2] = NAN;
  EXPECT_THROW(approximate_within_border(g, no_height, {.max_error = 1}), InputError);
}

// --- From files ---------------------------------------------------------------------------

std::string write_asc(const testing::TempDir& dir, const std::string& name, const HeightGrid& g) {
  std::string text = "ncols " + std::to_string(g.nx) + "\nnrows " + std::to_string(g.ny) +
                     "\nxllcorner 0\nyllcorner 0\ncellsize " + std::to_string(g.dx) + "\nNODATA_value -9999\n";
  for (std::size_t r = 0; r < g.ny; ++r) {
    const std::size_t j = g.ny - 1 - r;
    for (std::size_t i = 0; i < g.nx; ++i) {
      char v[32];
      std::snprintf(v, sizeof v, "%.9g ", g.has_data(i, j) ? static_cast<double>(g.at(i, j)) : -9999.0);
      text += v;
    }
    text += '\n';
  }
  return dir.write(name, text);
}

TEST(TerrainTiles, AGridFileIsCutAsTheSameGridInMemory) {
  testing::TempDir dir;
  HeightGrid g = rough_hills(33, 26, 9, 5.0, 5.0);
  g.z[7 + 10 * g.nx] = NAN;
  const std::string path = write_asc(dir, "g.asc", g);
  // The rows come northernmost first and are the whole grid's rows.
  const HeightGrid whole = read_height_grid(path);
  std::vector<std::size_t> order;
  const HeightGrid header = read_height_grid_rows(path, {}, [&](const HeightGrid& h, std::size_t j, std::span<const float> z) {
    EXPECT_EQ(h.nx, whole.nx);
    EXPECT_EQ(h.dx, whole.dx);
    ASSERT_EQ(z.size(), whole.nx);
    EXPECT_EQ(0, std::memcmp(z.data(), whole.z.data() + j * whole.nx, z.size() * sizeof(float))) << j;
    order.push_back(j);
  });
  EXPECT_TRUE(header.z.empty());
  ASSERT_EQ(order.size(), whole.ny);
  for (std::size_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], whole.ny - 1 - k);

  std::vector<Tile> from_file, from_memory;
  cut_tiles(path, {}, 8, std::nullopt, [&](const Tile& t) { from_file.push_back(t); });
  cut_tiles(whole, 8, std::nullopt, [&](const Tile& t) { from_memory.push_back(t); });
  ASSERT_EQ(from_file.size(), from_memory.size());
  for (std::size_t k = 0; k < from_file.size(); ++k) {
    EXPECT_EQ(from_file[k].index, from_memory[k].index);
    EXPECT_EQ(from_file[k].corner_heights, from_memory[k].corner_heights);
    EXPECT_EQ(0, std::memcmp(from_file[k].grid.z.data(), from_memory[k].grid.z.data(),
                             from_file[k].grid.z.size() * sizeof(float)));
  }
}

TEST(TerrainTiles, ABadFileIsRefusedEvenWhenItsTileIsAboveTheProblem) {
  testing::TempDir dir;
  const HeightGrid g = rough_hills(12, 12, 10);
  std::string text = testing::slurp(write_asc(dir, "g.asc", g));
  const std::string cut = dir.write("cut.asc", text.substr(0, text.rfind('\n', text.size() - 2) + 1));
  std::vector<TileIndex> seen;
  try {
    cut_tiles(cut, {}, 4, TileIndex{3, 0}, [&](const Tile& t) { seen.push_back(t.index); });
    ADD_FAILURE() << "a truncated grid was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(cut + ":"), std::string::npos) << e.what();
  }
  EXPECT_EQ(seen.size(), 1u) << "the northern tile was handed over before the end was found short";
}

}  // namespace
}  // namespace meshstep::terrain
