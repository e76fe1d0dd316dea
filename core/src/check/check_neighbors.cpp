// Stage 6: stored neighbors must match what the triangles say: neighbor i of triangle t is
// the triangle across the edge opposite corner i, kNoIndex exactly on boundary edges.
#include "check/stages.hpp"

namespace meshstep::check_detail {
namespace {

std::string neighbor_text(const MeshFacts& facts, std::uint32_t t) {
  return t == kNoIndex ? std::string("none") : "triangle " + number(t, facts.mesh.first_index);
}

}  // namespace

void check_neighbors(MeshFacts& facts) {
  const auto& mesh = facts.mesh;
  if (mesh.neighbors.empty()) return;
  if (mesh.neighbors.size() != mesh.triangles.size()) {
    facts.log.add([&] {
      return "the mesh lists neighbors for " + std::to_string(mesh.neighbors.size()) +
             " triangles but has " + std::to_string(mesh.triangles.size()) + " triangles";
    });
    return;
  }
  const EdgeTable& table = *facts.edges;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!facts.usable(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t twin = table.twin(static_cast<std::uint32_t>(3 * t + i));
      if (twin == EdgeTable::kNonManifold) continue;  // no right answer; reported already
      const std::uint32_t expected = twin == EdgeTable::kBoundary ? kNoIndex : twin / 3;
      const std::uint32_t stored = mesh.neighbors[t][i];
      if (stored == expected) continue;
      facts.log.add([&] {
        const auto& tri = mesh.triangles[t];
        return facts.triangle(t) + ": neighbor " + std::to_string(i) + " (across edge " +
               facts.vertex(tri[(i + 1) % 3]) + " " + facts.vertex(tri[(i + 2) % 3]) + ") is " +
               neighbor_text(facts, stored) + ", expected " + neighbor_text(facts, expected);
      });
    }
  }
}

}  // namespace meshstep::check_detail
