// make_grid COLUMNS ROWS OUT.asc [--cell C] [--seed S] [--nodata-square K]
//
// Writes a synthetic terrain as an ESRI ASCII grid, row by row (nothing but one row is held,
// so a grid of 1e8 samples and 800 MB costs a few kB of memory): the input of the tiled
// terrain benchmark (tile_bench.sh, docs/terrain.md "Tiles").
//
// Heights are a sum of 16 plane waves in directions and phases drawn from the seed, their
// wavelengths spread evenly in log scale from 8 cells to the grid's longer side, each with
// an amplitude in proportion to its wavelength (a 1/f spectrum: detail at every scale, as
// real terrain has, so a larger grid needs more triangles), scaled into 0..2000 m and
// written with centimetres. A wave sin(a i + b j + p) is sin(a i) cos(b j + p) + cos(a i)
// sin(b j + p): per column and per row terms computed once, two products a sample.
// --nodata-square K makes every K-th square of K x K cells NODATA (-9999), down the grid's
// diagonal, so that tile borders and corners cross holes.
//
// Exit status: 0 written, 1 cannot write, 2 usage error.
#include <array>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "bench_args.hpp"

namespace {

constexpr const char* kUsage = "usage: make_grid COLUMNS ROWS OUT.asc [--cell C] [--seed S] [--nodata-square K]\n";

constexpr int kWaves = 16;

struct Wave {
  double a, b, phase, amplitude;  // radians per column and per row
};

std::array<Wave, kWaves> make_waves(std::size_t longest, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::array<Wave, kWaves> waves{};
  const double shortest = 8.0;
  for (int k = 0; k < kWaves; ++k) {
    const double wavelength = shortest * std::pow(static_cast<double>(longest) / shortest, k / (kWaves - 1.0));
    const double direction = 2.0 * std::numbers::pi * unit(rng);
    const double frequency = 2.0 * std::numbers::pi / wavelength;
    waves[k] = {frequency * std::cos(direction), frequency * std::sin(direction), 2.0 * std::numbers::pi * unit(rng),
                wavelength};
  }
  return waves;
}

}  // namespace

int main(int argc, char** argv) {
  using meshstep::bench::parse_whole;
  using meshstep::bench::usage_error;
  if (argc < 4) return usage_error("make_grid", "expected COLUMNS ROWS OUT.asc", kUsage);
  std::size_t nx = 0, ny = 0, nodata_square = 0;
  double cell = 10.0;
  std::uint64_t seed = 1;
  if (!parse_whole(argv[1], nx) || !parse_whole(argv[2], ny) || nx < 2 || ny < 2)
    return usage_error("make_grid", "COLUMNS and ROWS must be whole numbers >= 2", kUsage);
  for (int k = 4; k < argc; k += 2) {
    const std::string option = argv[k];
    if (k + 1 >= argc) return usage_error("make_grid", option + " needs a value", kUsage);
    const bool ok = option == "--cell"            ? parse_whole(argv[k + 1], cell) && cell > 0.0
                    : option == "--seed"          ? parse_whole(argv[k + 1], seed)
                    : option == "--nodata-square" ? parse_whole(argv[k + 1], nodata_square) && nodata_square > 0
                                                  : false;
    if (!ok) return usage_error("make_grid", "bad option " + option + " " + argv[k + 1], kUsage);
  }

  const std::array<Wave, kWaves> waves = make_waves(std::max(nx, ny), seed);
  // The sum's extremes are at most the sum of the amplitudes: scale that into 0..2000 m.
  double total = 0.0;
  for (const Wave& w : waves) total += w.amplitude;
  const double scale = 1000.0 / total;

  std::vector<double> sin_i(kWaves * nx), cos_i(kWaves * nx);
  for (std::size_t i = 0; i < nx; ++i)
    for (int k = 0; k < kWaves; ++k) {
      sin_i[k * nx + i] = std::sin(waves[k].a * static_cast<double>(i));
      cos_i[k * nx + i] = std::cos(waves[k].a * static_cast<double>(i));
    }

  std::FILE* out = std::fopen(argv[3], "wb");
  if (!out) {
    std::fprintf(stderr, "make_grid: error: %s: %s\n", argv[3], std::strerror(errno));
    return 1;
  }
  std::fprintf(out, "ncols %zu\nnrows %zu\nxllcorner 0\nyllcorner 0\ncellsize %.17g\nNODATA_value -9999\n", nx, ny,
               cell);
  std::vector<double> row(nx);
  std::string line;
  for (std::size_t r = 0; r < ny; ++r) {
    const std::size_t j = ny - 1 - r;  // the file's first row is the northernmost
    std::fill(row.begin(), row.end(), 0.0);
    for (int k = 0; k < kWaves; ++k) {
      const double s = std::sin(waves[k].b * static_cast<double>(j) + waves[k].phase) * waves[k].amplitude;
      const double c = std::cos(waves[k].b * static_cast<double>(j) + waves[k].phase) * waves[k].amplitude;
      const double* si = &sin_i[k * nx];
      const double* ci = &cos_i[k * nx];
      for (std::size_t i = 0; i < nx; ++i) row[i] += si[i] * c + ci[i] * s;
    }
    line.clear();
    for (std::size_t i = 0; i < nx; ++i) {
      const bool hole = nodata_square > 0 && (i / nodata_square) % 2 == 1 && i / nodata_square == j / nodata_square;
      char text[32];
      const double h = std::round((1000.0 + row[i] * scale) * 100.0) / 100.0;
      const auto [end, ec] = hole ? std::to_chars(text, text + sizeof text, -9999)
                                  : std::to_chars(text, text + sizeof text, h, std::chars_format::fixed, 2);
      line.append(text, end);
      line += i + 1 < nx ? ' ' : '\n';
    }
    if (std::fwrite(line.data(), 1, line.size(), out) != line.size()) {
      std::fprintf(stderr, "make_grid: error: %s: %s\n", argv[3], std::strerror(errno));
      std::fclose(out);
      return 1;
    }
  }
  if (std::fclose(out) != 0) {
    std::fprintf(stderr, "make_grid: error: %s: %s\n", argv[3], std::strerror(errno));
    return 1;
  }
  return 0;
}
