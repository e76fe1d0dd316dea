// approximate(): the terrain algorithms on either data structure, and their registry.
#include "meshstep/terrain/tin.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"
#include "meshstep/replay/recorder.hpp"
#include "tin_builder.hpp"

namespace meshstep::terrain {
namespace {

constexpr std::array kAlgorithms{
    TerrainAlgorithmInfo{"lepp-surface",
                         "worst triangle by vertical error, its longest-edge propagating path (3D lengths); "
                         "the terminal triangles' worst sample while they miss the bound, else the sample nearest "
                         "their centroid (after Coll, Guerrieri, Rivara, Sellares 2008; docs/terrain.md)",
                         TerrainAlgorithm::lepp_surface},
    TerrainAlgorithmInfo{"greedy",
                         "the sample of largest vertical error, Delaunay in the plane (Garland and Heckbert 1995; "
                         "what hmm and delatin do)",
                         TerrainAlgorithm::greedy},
};

// The builder on the options' data structure, recording into options.record when set.
template <TriangleMesh Mesh>
Tin build_on(const HeightGrid& grid, const TerrainOptions& options, const BorderVertices* border, TerrainReport& r) {
  if (!options.record) return detail::TinBuilder<Mesh>(grid, options, border).run(r);
  return detail::TinBuilder<Mesh, replay::Recorder>(grid, options, border, replay::Recorder(*options.record)).run(r);
}

Tin build(const HeightGrid& grid, const TerrainOptions& options, const BorderVertices* border, TerrainReport& r) {
  if (options.data_structure == DataStructure::dcel) return build_on<Dcel>(grid, options, border, r);
  return build_on<Tds>(grid, options, border, r);
}

}  // namespace

std::span<const TerrainAlgorithmInfo> terrain_algorithms() { return kAlgorithms; }

const TerrainAlgorithmInfo* find_terrain_algorithm(std::string_view name) {
  for (const auto& a : kAlgorithms)
    if (a.name == name) return &a;
  return nullptr;
}

Tin approximate(const HeightGrid& grid, const TerrainOptions& options, TerrainReport* report) {
  if (!(options.max_error >= 0.0)) throw InputError("the largest error must be a number >= 0");
  TerrainReport local;
  TerrainReport& r = report ? *report : local;
  return build(grid, options, nullptr, r);
}

namespace {

// The rules approximate_within_border states, checked: a broken border would make a TIN
// with holes or crossing edges, not an error message.
void check_border(const HeightGrid& grid, const BorderVertices& border) {
  if (grid.nx < 2 || grid.ny < 2) throw InputError("a terrain needs a grid of at least 2 x 2 samples");
  if (border.samples.size() != border.heights.size())
    throw InputError("the border has " + std::to_string(border.samples.size()) + " samples but " +
                     std::to_string(border.heights.size()) + " heights");
  if (border.samples.size() < 4) throw InputError("the border needs at least the grid's four corners");
  const std::size_t last_i = grid.nx - 1, last_j = grid.ny - 1;
  const std::array<std::size_t, 4> corners{0, last_i, last_i + last_j * grid.nx, last_j * grid.nx};
  for (std::size_t k = 0; k < 4; ++k)
    if (border.samples[k] != corners[k])
      throw InputError("border vertex " + std::to_string(k) + " must be corner sample " + std::to_string(corners[k]));
  std::vector<bool> seen(grid.nx * grid.ny, false);
  for (std::size_t k = 0; k < border.samples.size(); ++k) {
    const std::uint32_t s = border.samples[k];
    if (s >= seen.size()) throw InputError("border sample " + std::to_string(s) + " is outside the grid");
    const std::size_t i = s % grid.nx, j = s / grid.nx;
    if (i != 0 && j != 0 && i != last_i && j != last_j)
      throw InputError("border sample " + std::to_string(s) + " is not on the grid's rectangle");
    if (seen[s]) throw InputError("border sample " + std::to_string(s) + " is given twice");
    seen[s] = true;
    if (!std::isfinite(border.heights[k]))
      throw InputError("border sample " + std::to_string(s) + " has no height");
  }
}

}  // namespace

Tin approximate_within_border(const HeightGrid& grid, const BorderVertices& border, const TerrainOptions& options,
                              TerrainReport* report) {
  if (!(options.max_error >= 0.0)) throw InputError("the largest error must be a number >= 0");
  check_border(grid, border);
  TerrainReport local;
  TerrainReport& r = report ? *report : local;
  return build(grid, options, &border, r);
}

std::array<double, 3> vertex_position(const HeightGrid& grid, const Tin& tin, std::uint32_t v) {
  const std::size_t i = tin.samples[v] % grid.nx, j = tin.samples[v] / grid.nx;
  return {static_cast<double>(i) * grid.dx, static_cast<double>(j) * grid.dy, tin.heights[v]};
}

}  // namespace meshstep::terrain
