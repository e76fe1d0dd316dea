// Stage 1: everything later stages index with must be in range and well formed.
#include <algorithm>
#include <array>
#include <cmath>

#include "check/stages.hpp"

namespace meshstep::check_detail {
namespace {

void check_points(MeshFacts& facts) {
  const auto& points = facts.mesh.points;
  facts.finite_point.assign(points.size(), 1);
  for (std::size_t v = 0; v < points.size(); ++v) {
    if (std::isfinite(points[v].x) && std::isfinite(points[v].y)) continue;
    facts.finite_point[v] = 0;
    facts.log.add([&] {
      return "vertex " + facts.vertex(v) + " has a non-finite coordinate " +
             point_text(points[v].x, points[v].y);
    });
  }
}

void check_triangle_indices(MeshFacts& facts) {
  const auto& mesh = facts.mesh;
  const std::size_t n = mesh.points.size();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (std::uint32_t v : tri) {
      if (v < n) continue;
      facts.tri_state[t] = TriState::kBadIndices;
      facts.log.add([&] {
        return facts.triangle(t) + " refers to vertex " + facts.vertex(v) + ", but the mesh has " +
               std::to_string(n) + " vertices";
      });
      break;
    }
    if (facts.tri_state[t] == TriState::kBadIndices) continue;
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      facts.tri_state[t] = TriState::kBadIndices;
      facts.log.add([&] { return facts.triangle(t) + " uses the same vertex twice"; });
    }
  }
}

// The same vertex set listed twice. Same orientation would also show up as an edge used
// twice the same way, but opposite orientation looks like two triangles glued along all
// three edges, which the edge stage cannot tell from a valid pair.
void check_duplicate_triangles(MeshFacts& facts) {
  const auto& tris = facts.mesh.triangles;
  struct Entry {
    std::array<std::uint32_t, 3> sorted;
    std::uint32_t t;
  };
  std::vector<Entry> entries;
  entries.reserve(tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    if (!facts.usable(t)) continue;
    auto sorted = tris[t];
    std::sort(sorted.begin(), sorted.end());
    entries.push_back({sorted, static_cast<std::uint32_t>(t)});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.sorted < b.sorted || (a.sorted == b.sorted && a.t < b.t);
  });
  for (std::size_t k = 1; k < entries.size(); ++k) {
    if (entries[k].sorted != entries[k - 1].sorted) continue;
    facts.log.add([&] {
      return facts.triangle(entries[k - 1].t) + " and triangle " +
             number(entries[k].t, facts.mesh.first_index) + " have the same three vertices";
    });
  }
}

void check_segment_indices(MeshFacts& facts) {
  const auto& mesh = facts.mesh;
  for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
    const Segment& seg = mesh.segments[s];
    if (seg.a < mesh.points.size() && seg.b < mesh.points.size()) continue;
    facts.log.add([&] {
      return "segment " + number(s, mesh.first_index) + " (vertices " + facts.vertex(seg.a) + " " +
             facts.vertex(seg.b) + ") refers to a vertex the mesh does not have";
    });
  }
}

}  // namespace

void check_indices(MeshFacts& facts) {
  facts.tri_state.assign(facts.mesh.triangles.size(), TriState::kNotCcw);
  check_points(facts);
  check_triangle_indices(facts);
  check_duplicate_triangles(facts);
  check_segment_indices(facts);
}

}  // namespace meshstep::check_detail
