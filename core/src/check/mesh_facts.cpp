// Shared helpers of the check stages.
#include <utility>

#include "check/stages.hpp"

namespace meshstep::check_detail {

std::string MeshFacts::triangle(std::size_t t) const {
  const auto& tri = mesh.triangles[t];
  return "triangle " + number(t, mesh.first_index) + " (vertices " + vertex(tri[0]) + " " +
         vertex(tri[1]) + " " + vertex(tri[2]) + ")";
}

// Flags on edge ids instead of a set of vertex pairs: the Delaunay stage then asks about
// every interior edge in O(1), with no hashing and no cache-missing binary search.
void MeshFacts::mark_listed_edges() {
  listed_edge.assign(mesh.triangles.size() * 3, 0);
  for (const Segment& s : mesh.segments) {
    if (s.a >= mesh.points.size() || s.b >= mesh.points.size()) continue;  // reported
    for (const auto& e : edges->out_to(s.a, s.b)) listed_edge[e.edge] = 1;
    for (const auto& e : edges->out_to(s.b, s.a)) listed_edge[e.edge] = 1;
  }
}

bool MeshFacts::is_listed(std::uint32_t v, std::uint32_t w) const {
  for (auto [from, to] : {std::pair{v, w}, std::pair{w, v}}) {
    const auto run = edges->out_to(from, to);
    if (!run.empty()) return listed_edge[run.front().edge] != 0;
  }
  return false;
}

const BoxTree& MeshFacts::triangle_tree() {
  if (!good_triangles) {
    std::vector<std::uint32_t> good;
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
      if (this->good(t)) good.push_back(t);
    good_triangles.emplace(good, [&](std::uint32_t t) {
      BBox box;
      for (std::uint32_t v : mesh.triangles[t]) box.add(mesh.points[v]);
      return box;
    });
  }
  return *good_triangles;
}

}  // namespace meshstep::check_detail
