// approximate(): the terrain algorithms on either data structure, and their registry.
#include "meshstep/terrain/tin.hpp"

#include <array>
#include <cmath>

#include "meshstep/error.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"
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
  if (options.data_structure == DataStructure::dcel) return detail::TinBuilder<Dcel>(grid, options).run(r);
  return detail::TinBuilder<Tds>(grid, options).run(r);
}

std::array<double, 3> vertex_position(const HeightGrid& grid, const Tin& tin, std::uint32_t v) {
  const std::size_t i = tin.samples[v] % grid.nx, j = tin.samples[v] / grid.nx;
  return {static_cast<double>(i) * grid.dx, static_cast<double>(j) * grid.dy, tin.heights[v]};
}

}  // namespace meshstep::terrain
