// tile_check GRID.asc TILE... [--bound E]
//
// The tiled terrain benchmark's own check of a run's output (tile_bench.sh), apart from
// meshstep's: the grid is read whole (it is a checker, not the tiled program: 4 bytes and
// a bit a sample), every tile file is read back, each vertex is mapped to its sample (its x and y
// must be exactly i dx and j dy, its height the sample's where the sample has data), and
// every sample with data is measured against every triangle whose bounding box holds it,
// by barycentric weights in doubles (not meshstep's integer row scan). Prints one line:
//   samples N uncovered U max_error E at i,j vertices_off_grid V heights_off W
// Exit status: 0 when every sample is covered, every vertex is a sample and (given
// --bound) the largest error is within E (1e-9 relative slack for the rounding of doubles);
// 1 otherwise; 2 usage error.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/terrain/height_grid.hpp"

namespace {

constexpr const char* kUsage = "usage: tile_check GRID.asc TILE... [--bound E]\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace meshstep;
  if (argc < 3) return bench::usage_error("tile_check", "expected a grid and tile files", kUsage);
  std::vector<std::string> tiles;
  double bound = -1.0;
  for (int k = 2; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--bound") {
      if (k + 1 >= argc || !bench::parse_whole(argv[k + 1], bound))
        return bench::usage_error("tile_check", "--bound needs a number", kUsage);
      ++k;
    } else {
      tiles.push_back(arg);
    }
  }
  try {
    const terrain::HeightGrid g = terrain::read_height_grid(argv[1]);
    std::vector<bool> covered(g.nx * g.ny, false);
    double worst = 0.0;
    std::size_t worst_sample = 0, off_grid = 0, heights_off = 0;
    for (const std::string& path : tiles) {
      const io::Surface s = io::read_surface(path);
      std::vector<double> vi(s.vertices.size()), vj(s.vertices.size());
      for (std::size_t v = 0; v < s.vertices.size(); ++v) {
        const auto& p = s.vertices[v];
        vi[v] = std::round(p.x / g.dx);
        vj[v] = std::round(p.y / g.dy);
        const bool inside = vi[v] >= 0 && vj[v] >= 0 && vi[v] < static_cast<double>(g.nx) &&
                            vj[v] < static_cast<double>(g.ny);
        if (!inside || vi[v] * g.dx != p.x || vj[v] * g.dy != p.y) {
          ++off_grid;
          continue;
        }
        const auto i = static_cast<std::size_t>(vi[v]), j = static_cast<std::size_t>(vj[v]);
        if (g.has_data(i, j) && static_cast<double>(g.at(i, j)) != p.z) ++heights_off;
      }
      for (const auto& t : s.triangles) {
        const double x0 = vi[t[0]], y0 = vj[t[0]], x1 = vi[t[1]], y1 = vj[t[1]], x2 = vi[t[2]], y2 = vj[t[2]];
        const double det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
        if (det <= 0.0) continue;  // not counter-clockwise: its samples show up uncovered
        const double z0 = s.vertices[t[0]].z, z1 = s.vertices[t[1]].z, z2 = s.vertices[t[2]].z;
        const auto lo_i = static_cast<std::size_t>(std::max(0.0, std::min({x0, x1, x2})));
        const auto hi_i = static_cast<std::size_t>(std::min(static_cast<double>(g.nx - 1), std::max({x0, x1, x2})));
        const auto lo_j = static_cast<std::size_t>(std::max(0.0, std::min({y0, y1, y2})));
        const auto hi_j = static_cast<std::size_t>(std::min(static_cast<double>(g.ny - 1), std::max({y0, y1, y2})));
        for (std::size_t j = lo_j; j <= hi_j; ++j)
          for (std::size_t i = lo_i; i <= hi_i; ++i) {
            const double px = static_cast<double>(i), py = static_cast<double>(j);
            // Integer coordinates: these edge functions are exact in doubles.
            const double w1 = (px - x0) * (y2 - y0) - (x2 - x0) * (py - y0);
            const double w2 = (x1 - x0) * (py - y0) - (px - x0) * (y1 - y0);
            const double w0 = det - w1 - w2;
            if (w0 < 0 || w1 < 0 || w2 < 0) continue;
            const std::size_t sample = i + j * g.nx;
            if (std::isnan(g.z[sample])) continue;
            const double e = std::fabs(g.z[sample] - (w0 * z0 + w1 * z1 + w2 * z2) / det);
            covered[sample] = true;
            if (e > worst) {
              worst = e;
              worst_sample = sample;
            }
          }
      }
    }
    std::size_t samples = 0, uncovered = 0;
    for (std::size_t s = 0; s < covered.size(); ++s) {
      if (std::isnan(g.z[s])) continue;
      ++samples;
      uncovered += !covered[s];
    }
    std::printf("samples %zu uncovered %zu max_error %.9g at %zu,%zu vertices_off_grid %zu heights_off %zu\n", samples,
                uncovered, worst, worst_sample % g.nx, worst_sample / g.nx, off_grid, heights_off);
    const bool ok = uncovered == 0 && off_grid == 0 && heights_off == 0 && (bound < 0 || worst <= bound * (1 + 1e-9));
    return ok ? 0 : 1;
  } catch (const InputError& e) {
    std::fprintf(stderr, "tile_check: error: %s\n", e.what());
    return 1;
  }
}
