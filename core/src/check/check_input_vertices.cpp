// Stage 7a: the output keeps the input vertices first and in order, and a triangulator has
// no business moving one, not even by an ulp (or from 0.0 to -0.0): compare bit patterns.
#include <bit>

#include "check/stages.hpp"

namespace meshstep::check_detail {
namespace {

bool same_bits(const Point& a, const Point& b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
         std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y);
}

}  // namespace

void check_input_vertices(MeshFacts& facts, const Pslg& input) {
  const auto& mesh = facts.mesh;
  if (mesh.points.size() < input.points.size()) {
    facts.log.add([&] {
      return "the mesh has " + std::to_string(mesh.points.size()) + " vertices, fewer than the " +
             std::to_string(input.points.size()) + " input vertices";
    });
  }
  const std::size_t n = std::min(mesh.points.size(), input.points.size());
  for (std::size_t v = 0; v < n; ++v) {
    if (same_bits(mesh.points[v], input.points[v])) continue;
    facts.log.add([&] {
      const Point &m = mesh.points[v], &in = input.points[v];
      return "vertex " + facts.vertex(v) + " is " + point_text(m.x, m.y) +
             " but input vertex " + number(v, input.first_index) + " is " + point_text(in.x, in.y) +
             ": input vertices must be kept first, in order and unmoved";
    });
  }
}

}  // namespace meshstep::check_detail
