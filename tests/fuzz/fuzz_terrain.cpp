// Height grids (ESRI ASCII) and the terrain algorithms on them: whatever grid reads, both
// algorithms on both data structures, and the tiles' path (the grid read again row by row
// and cut), under a bound drawn for the input, give TINs that cover every sample with data
// within the bound, from runs that end; and a recorded run (lepp-surface, improved, flipped
// in 3D) gives the same TIN and a log that replays forward and backward to it.
//
// The bound. A first line "# bound E" or "# bound P%" (a comment to the grid reader) sets it,
// as `--max-error` reads it, so that a regression input keeps the bound it was found under.
// Otherwise it is drawn from a hash of the input's bytes, so that each input keeps its own
// and each mutation draws another: 0, rounding-level and subnormal bounds (a run once never
// ended under those), absolute bounds on the scale of the heights, and percentages of the
// height span (computed as the command computes them: a span in float once overflowed).
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

#include "fuzz_support.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/verify.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tiles.hpp"
#include "meshstep/terrain/tin.hpp"

using namespace meshstep;

namespace {

std::uint64_t fnv1a(const std::uint8_t* data, std::size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t k = 0; k < size; ++k) h = (h ^ data[k]) * 1099511628211ull;
  return h;
}

// "# bound E" or "# bound P%" on the first line: the bound it gives (-1: no such line).
double stated_bound(std::string_view text, double span) {
  constexpr std::string_view kTag = "# bound ";
  if (text.substr(0, kTag.size()) != kTag) return -1.0;
  text.remove_prefix(kTag.size());
  text = text.substr(0, text.find('\n'));
  const bool percent = !text.empty() && text.back() == '%';
  if (percent) text.remove_suffix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !(value >= 0.0)) return -1.0;
  return percent ? value / 100.0 * span : value;
}

double drawn_bound(std::uint64_t h, double span) {
  const std::uint64_t r = h >> 8;
  switch (h % 8) {
    case 0: return 0.0;
    case 1: return 5.55e-17 * static_cast<double>(r % 4);             // rounding-level
    case 2: return std::ldexp(1.0, -static_cast<int>(40 + r % 1040));  // tiny, down to subnormal
    case 3:
    case 4: return span * static_cast<double>(r % 1000) / 1000.0;     // absolute, within the span
    default: {
      constexpr double kPercents[] = {0.0, 1e-14, 0.1, 0.5, 1.0, 10.0, 50.0, 100.0, 150.0};
      return kPercents[r % std::size(kPercents)] / 100.0 * span;      // as --max-error P% takes it
    }
  }
}

void check_tin(const terrain::HeightGrid& grid, const terrain::Tin& tin, const terrain::TerrainReport& report,
               double bound, const char* what) {
  const terrain::ErrorMeasure error = terrain::measure_error(grid, tin);
  if (error.uncovered != 0) fuzz::finding(std::string(what) + ": a sample with data outside the TIN");
  if (!(error.max <= bound)) fuzz::finding(std::string(what) + ": a sample beyond the bound");
  if (report.capped) fuzz::finding(std::string(what) + ": capped without a cap");
  // Each insertion takes a sample that is not a vertex yet: a run that ends does at most this.
  if (report.insertions > grid.nx * grid.ny) fuzz::finding(std::string(what) + ": more insertions than samples");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::refusals_allowed([&] {
    const std::string& path = fuzz::write_input(data, size, ".asc");
    const terrain::HeightGrid grid = terrain::read_height_grid(path);
    if (grid.z.size() != grid.nx * grid.ny) fuzz::finding("a grid whose heights do not fill it");
    if (grid.nx * grid.ny > 4096) return;  // the algorithms' cost, not their correctness
    const double span = terrain::height_span(grid.height_range());
    const std::uint64_t h = fnv1a(data, size);
    const double stated = stated_bound(std::string_view(reinterpret_cast<const char*>(data), size), span);
    const double bound = stated >= 0.0 ? stated : drawn_bound(h, span);
    const bool improve = (h >> 40) & 1;
    for (const auto algorithm : {terrain::TerrainAlgorithm::greedy, terrain::TerrainAlgorithm::lepp_surface}) {
      for (const auto ds : {DataStructure::tds, DataStructure::dcel}) {
        terrain::TerrainOptions options;
        options.algorithm = algorithm;
        options.data_structure = ds;
        options.max_error = bound;
        options.improve = improve;
        terrain::TerrainReport report;
        const terrain::Tin tin = terrain::approximate(grid, options, &report);
        check_tin(grid, tin, report, bound, "whole grid");
      }
    }

    // The tiles' path, as `--tile N` runs it: the file read again row by row and cut.
    terrain::TerrainOptions tile_options;
    tile_options.algorithm = (h >> 41) & 1 ? terrain::TerrainAlgorithm::greedy : terrain::TerrainAlgorithm::lepp_surface;
    tile_options.max_error = bound;
    tile_options.improve = improve;
    const std::size_t tile_size = 2 + (h >> 42) % 7;
    terrain::cut_tiles(path, {}, tile_size, std::nullopt, [&](const terrain::Tile& tile) {
      terrain::TerrainReport report;
      const terrain::Tin tin = terrain::approximate_tile(tile, tile_options, &report);
      check_tin(tile.grid, tin, report, bound, "tile");
    });

    terrain::TerrainOptions options;
    options.max_error = bound;
    options.improve = true;
    options.flips_3d = true;
    const terrain::Tin plain = terrain::approximate(grid, options);
    const std::string log_path = (std::filesystem::temp_directory_path() / "fuzz_terrain.mslog").string();
    {
      replay::LogWriter writer(log_path, replay::LogHeader{});
      options.record = &writer;
      const terrain::Tin recorded = terrain::approximate(grid, options);
      writer.finish();
      if (recorded.samples != plain.samples || recorded.triangles != plain.triangles)
        fuzz::finding("recording changed the TIN");
    }
    const replay::LogReader log(log_path);
    const replay::VerifyReport verified = replay::verify(log);
    if (!verified.ok) fuzz::finding("a terrain run's log does not replay: " + verified.problem);
  });
  return 0;
}
