// The range rule on terrains: a grid's sample positions are scaled by a power of two into
// the window where the predicates are exact, as the plane's inputs are, so that a grid
// with cells of 2^-997 or 2^1017 m makes the TIN it makes with cells of 1 m; a grid whose
// extent is beyond the doubles is refused before any work.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"
#include "meshstep/terrain/tiles.hpp"

namespace meshstep::terrain {
namespace {

// A 12 x 12 grid of pseudo-random integer heights with square cells of `cell` m.
HeightGrid bumpy(double cell) {
  HeightGrid g;
  g.nx = g.ny = 12;
  g.dx = g.dy = cell;
  g.z.resize(g.nx * g.ny);
  for (std::size_t k = 0; k < g.z.size(); ++k) g.z[k] = static_cast<float>((k * 2654435761u >> 7) % 51);
  return g;
}

Tin greedy_tin(const HeightGrid& g) {
  TerrainOptions options;
  options.algorithm = TerrainAlgorithm::greedy;
  options.max_error = 0.0;
  return approximate(g, options);
}

TEST(TerrainRange, AnyCellSizeMakesTheTinOfUnitCells) {
  const Tin unit = greedy_tin(bumpy(1.0));
  ASSERT_GT(unit.triangles.size(), 100u);
  // Cells of 2^300 m: the incircle products overflow unscaled (a different TIN); cells of
  // 2^-997 m: the orientations underflow (the corners would look collinear). Both fail
  // without the scaling, quickly: the unbounded case below runs only once these pass.
  for (const int e : {300, -997}) {
    const Tin scaled = greedy_tin(bumpy(std::ldexp(1.0, e)));
    ASSERT_EQ(scaled.samples, unit.samples) << "cells of 2^" << e;
    ASSERT_EQ(scaled.triangles, unit.triangles) << "cells of 2^" << e;
  }
  // Cells of 2^1017 m (coordinates up to 1.5e307): unscaled, the orientations are NaN and
  // the point location walked round the hull for ever.
  const Tin huge = greedy_tin(bumpy(std::ldexp(1.0, 1017)));
  EXPECT_EQ(huge.samples, unit.samples);
  EXPECT_EQ(huge.triangles, unit.triangles);
}

TEST(TerrainRange, TilesOfHugeCellsMakeTheTilesOfUnitCells) {
  TerrainOptions options;
  options.algorithm = TerrainAlgorithm::greedy;
  std::vector<Tin> expected;
  cut_tiles(bumpy(1.0), 6, std::nullopt, [&](const Tile& t) { expected.push_back(approximate_tile(t, options)); });
  ASSERT_EQ(expected.size(), 9u);  // 3 x 3 tiles sharing their sides
  // 2^300 fails fast without the scaling; 2^1017 would not end, and runs only after it.
  for (const int e : {300, 1017}) {
    std::size_t tiles = 0;
    cut_tiles(bumpy(std::ldexp(1.0, e)), 6, std::nullopt, [&](const Tile& t) {
      ASSERT_LT(tiles, expected.size());
      const Tin tin = approximate_tile(t, options);
      EXPECT_EQ(tin.triangles, expected[tiles].triangles) << "cells of 2^" << e << ", tile " << tiles;
      ++tiles;
    });
    EXPECT_EQ(tiles, expected.size());
    ASSERT_FALSE(HasFailure());
  }
}

TEST(TerrainRange, AnExtentBeyondTheDoublesIsRefused) {
  // Three samples a row of 1e308 m: the far corner at 2e308 is no double.
  HeightGrid g = bumpy(1e308);
  try {
    greedy_tin(g);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("beyond the largest double"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace meshstep::terrain
