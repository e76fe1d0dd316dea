// Height grids (ESRI ASCII) and the terrain algorithms on them: whatever grid reads, both
// algorithms, with and without the improvement, give a TIN that covers every sample with
// data, within the bound; and a recorded run (lepp-surface, improved, flipped in 3D) gives
// the same TIN and a log that replays forward and backward to it.
#include <filesystem>

#include "fuzz_support.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/verify.hpp"
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
    terrain::TerrainOptions options;
    options.max_error = bound;
    options.improve = true;
    options.flips_3d = true;
    const terrain::Tin plain = terrain::approximate(grid, options);
    const std::string path = (std::filesystem::temp_directory_path() / "fuzz_terrain.mslog").string();
    {
      replay::LogWriter writer(path, replay::LogHeader{});
      options.record = &writer;
      const terrain::Tin recorded = terrain::approximate(grid, options);
      writer.finish();
      if (recorded.samples != plain.samples || recorded.triangles != plain.triangles)
        fuzz::finding("recording changed the TIN");
    }
    const replay::LogReader log(path);
    const replay::VerifyReport verified = replay::verify(log);
    if (!verified.ok) fuzz::finding("a terrain run's log does not replay: " + verified.problem);
  });
  return 0;
}
