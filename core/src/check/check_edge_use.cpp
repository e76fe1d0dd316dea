// Stage 3: a mesh edge has one triangle (boundary) or two on opposite sides (interior).
#include <algorithm>

#include "check/stages.hpp"

namespace meshstep::check_detail {
namespace {

std::string triangle_numbers(const MeshFacts& facts, std::span<const EdgeTable::Out> a,
                             std::span<const EdgeTable::Out> b) {
  std::string text;
  for (auto run : {a, b})
    for (const auto& e : run) {
      if (!text.empty()) text += ", ";
      text += number(e.edge / 3, facts.mesh.first_index);
    }
  return text;
}

}  // namespace

void check_edge_use(MeshFacts& facts) {
  const EdgeTable& table = *facts.edges;
  for (std::uint32_t v = 0; v < table.vertex_count(); ++v) {
    const auto edges = table.out(v);
    for (std::size_t r0 = 0; r0 < edges.size();) {
      std::size_t r1 = r0 + 1;
      const std::uint32_t w = edges[r0].dest;
      while (r1 < edges.size() && edges[r1].dest == w) ++r1;
      const auto same = edges.subspan(r0, r1 - r0);
      const auto back = table.out_to(w, v);
      r0 = r1;
      // Report each undirected edge once: from its smaller end, or from the only end that
      // has outgoing copies of it.
      if (!back.empty() && v > w) continue;
      const std::size_t uses = same.size() + back.size();
      // Formatted only when needed: this loop visits every edge of the mesh.
      auto name = [&] {
        return "edge (" + facts.vertex(std::min(v, w)) + " " + facts.vertex(std::max(v, w)) + ")";
      };
      if (uses > 2) {
        facts.log.add([&] {
          return name() + " is used by " + std::to_string(uses) +
                 " triangles: " + triangle_numbers(facts, same, back);
        });
      } else if (same.size() == 2 || back.size() == 2) {
        facts.log.add([&] {
          return name() + " is used twice in the same direction, so triangles " +
                 triangle_numbers(facts, same, back) + " lie on the same side of it";
        });
      }
    }
  }
}

}  // namespace meshstep::check_detail
