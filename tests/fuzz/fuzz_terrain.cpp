// Height grids (ESRI ASCII) and the terrain algorithms on them: whatever grid reads, both
// algorithms, with and without the improvement, give a TIN that covers every sample with
// data, within the bound.
#include "fuzz_support.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"

using namespace meshstep;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::refusals_allowed([&] {
    const terrain::HeightGrid grid = terrain::read_height_grid(fuzz::write_input(data, size, ".asc"));
    if (grid.z.size() != grid.nx * grid.ny) fuzz::finding("a grid whose heights do not fill it");
    if (grid.nx * grid.ny > 4096) return;  // the algorithms' cost, not their correctness
    const auto [low, high] = grid.height_range();
    const double bound = 0.01 * (static_cast<double>(high) - low);
    for (const auto algorithm : {terrain::TerrainAlgorithm::greedy, terrain::TerrainAlgorithm::lepp_surface}) {
      for (const bool improve : {false, true}) {
        terrain::TerrainOptions options;
        options.algorithm = algorithm;
        options.max_error = bound;
        options.improve = improve;
        const terrain::Tin tin = terrain::approximate(grid, options);
        const terrain::ErrorMeasure error = terrain::measure_error(grid, tin);
        if (error.uncovered != 0) fuzz::finding("a sample with data outside the TIN");
        if (!(error.max <= bound)) fuzz::finding("a sample beyond the bound");
      }
    }
  });
  return 0;
}
