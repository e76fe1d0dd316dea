// A tile's border, chosen from the border's samples alone (meshstep/terrain/tiles.hpp), and
// the tile's TIN from it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "meshstep/terrain/tiles.hpp"

namespace meshstep::terrain {
namespace {

// The nearest column to i where `heights` has data, ties to the west; nullopt if none.
std::optional<float> nearest_with_data(std::span<const float> heights, std::size_t i) {
  for (std::size_t d = 1; d <= i || i + d < heights.size(); ++d) {
    if (d <= i && !std::isnan(heights[i - d])) return heights[i - d];
    if (i + d < heights.size() && !std::isnan(heights[i + d])) return heights[i + d];
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::size_t> simplify_profile(std::span<const float> heights, float first, float last, double max_error) {
  const std::size_t n = heights.size();
  double largest = std::max(std::fabs(static_cast<double>(first)), std::fabs(static_cast<double>(last)));
  for (const float h : heights)
    if (!std::isnan(h)) largest = std::max(largest, std::fabs(static_cast<double>(h)));
  // Within this of the chord in 1D is within max_error in 2D: the plane of a triangle over
  // a border edge is the chord, but evaluated with other sums (triangle_scan.hpp), whose
  // rounding is far below a float32 step of the heights themselves.
  const double threshold = max_error - std::ldexp(largest, -22);

  std::vector<std::size_t> kept;
  struct Chord {
    std::size_t a, b;
  };
  const auto height_at = [&](std::size_t k) -> double {
    return k == 0 ? first : k == n - 1 ? last : heights[k];
  };
  std::vector<Chord> stack{{0, n - 1}};
  while (!stack.empty()) {
    const Chord c = stack.back();
    stack.pop_back();
    const double ha = height_at(c.a), hb = height_at(c.b);
    const double span = static_cast<double>(c.b - c.a);
    double worst = -1.0;
    std::size_t worst_k = 0;
    for (std::size_t k = c.a + 1; k < c.b; ++k) {
      const double chord = ha + (hb - ha) * (static_cast<double>(k - c.a) / span);
      const double error = std::fabs(static_cast<double>(heights[k]) - chord);
      if (error > worst) {  // false for NaN: no data, no error
        worst = error;
        worst_k = k;
      }
    }
    if (worst_k == 0 || !(worst > threshold)) continue;
    kept.push_back(worst_k);
    stack.push_back({worst_k, c.b});
    stack.push_back({c.a, worst_k});
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

float tile_corner_height(std::span<const float> row, std::span<const float> north, std::size_t i) {
  if (!std::isnan(row[i])) return row[i];
  if (const auto h = nearest_with_data(row, i)) return *h;
  if (!std::isnan(north[i])) return north[i];
  if (const auto h = nearest_with_data(north, i)) return *h;
  return 0.0f;
}

BorderVertices tile_border(const Tile& tile, double max_error) {
  const HeightGrid& g = tile.grid;
  const std::size_t nx = g.nx, ny = g.ny;
  const auto sample = [&](std::size_t i, std::size_t j) { return static_cast<std::uint32_t>(i + j * nx); };
  BorderVertices border;
  for (const std::uint32_t s : {sample(0, 0), sample(nx - 1, 0), sample(nx - 1, ny - 1), sample(0, ny - 1)})
    border.samples.push_back(s);
  border.heights.assign(tile.corner_heights.begin(), tile.corner_heights.end());

  // Each side west to east or south to north, as the neighbour that shares it reads it.
  std::vector<float> side;
  const auto add_side = [&](std::size_t i, std::size_t j, std::size_t di, std::size_t dj, std::size_t n, float first,
                            float last) {
    side.clear();
    for (std::size_t k = 0; k < n; ++k) side.push_back(g.at(i + k * di, j + k * dj));
    for (const std::size_t k : simplify_profile(side, first, last, max_error)) {
      border.samples.push_back(sample(i + k * di, j + k * dj));
      border.heights.push_back(side[k]);
    }
  };
  const auto [sw, se, ne, nw] = tile.corner_heights;
  add_side(0, 0, 1, 0, nx, sw, se);       // south
  add_side(nx - 1, 0, 0, 1, ny, se, ne);  // east
  add_side(0, ny - 1, 1, 0, nx, nw, ne);  // north
  add_side(0, 0, 0, 1, ny, sw, nw);       // west
  return border;
}

Tin approximate_tile(const Tile& tile, const TerrainOptions& options, TerrainReport* report) {
  return approximate_within_border(tile.grid, tile_border(tile, options.max_error), options, report);
}

}  // namespace meshstep::terrain
