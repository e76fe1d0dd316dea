// Stage 4b: no vertex, used or not, may lie strictly inside a triangle or in the relative
// interior of one of its edges unless it is that triangle's corner. Candidate pairs come
// from a box tree of the vertices, so the cost is about triangles x log(vertices) instead of
// triangles x vertices, whatever the distribution; the decision itself is exact orient2d.
#include <algorithm>

#include "check/stages.hpp"
#include "check/box_tree.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep::check_detail {

void check_vertices_in_triangles(MeshFacts& facts) {
  const auto& mesh = facts.mesh;
  const auto& p = mesh.points;
  // Only vertices inside the box of the good triangles can be inside one of them; leaving
  // the rest out keeps far-away unused vertices out of the tree.
  BBox box;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (facts.good(t))
      for (std::uint32_t v : mesh.triangles[t]) box.add(p[v]);
  if (box.empty()) return;
  std::vector<std::uint32_t> candidates;  // finite vertices inside the box
  candidates.reserve(p.size());
  for (std::uint32_t v = 0; v < p.size(); ++v) {
    if (facts.finite_point[v] && box_contains(box, p[v])) candidates.push_back(v);
  }
  const BoxTree tree(candidates, [&](std::uint32_t v) {
    BBox point_box;
    point_box.add(p[v]);
    return point_box;
  });

  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!facts.good(t)) continue;
    const auto& tri = mesh.triangles[t];
    const Point &a = p[tri[0]], &b = p[tri[1]], &c = p[tri[2]];
    BBox tri_box;
    for (const Point* corner : {&a, &b, &c}) tri_box.add(*corner);
    // A node is skipped when its box misses the triangle's box or lies strictly outside one
    // of its edges; a box holding a corner cannot be outside, which spares the predicates
    // for the upper levels of the tree.
    auto skip = [&](const BBox& node) {
      if (!boxes_overlap(node, tri_box)) return true;
      if (box_contains(node, a) || box_contains(node, b) || box_contains(node, c)) return false;
      return box_right_of(node, a, b) || box_right_of(node, b, c) || box_right_of(node, c, a);
    };
    tree.query(skip, [&](std::uint32_t v) {
      const Point& q = p[v];
      if (!box_contains(tri_box, q)) return;
      if (v == tri[0] || v == tri[1] || v == tri[2]) return;
      // o[i]: side of q relative to the edge opposite corner i (> 0: the inner side).
      const double o[3] = {orient2d(b, c, q), orient2d(c, a, q), orient2d(a, b, q)};
      if (o[0] < 0.0 || o[1] < 0.0 || o[2] < 0.0) return;
      const int zeros = (o[0] == 0.0) + (o[1] == 0.0) + (o[2] == 0.0);
      if (zeros >= 2) return;  // at a corner's position: a duplicate vertex, allowed
      if (zeros == 0) {
        facts.log.add([&] {
          return "vertex " + facts.vertex(v) + " " + point_text(q.x, q.y) + " lies inside " +
                 facts.triangle(t);
        });
        return;
      }
      const int i = o[0] == 0.0 ? 0 : (o[1] == 0.0 ? 1 : 2);
      // An interior edge is seen from both of its triangles: report it from one.
      const auto edge = static_cast<std::uint32_t>(3 * t + i);
      const std::uint32_t twin = facts.edges->twin(edge);
      if (twin < edge && facts.good(twin / 3)) return;  // sentinels are larger than any id
      facts.log.add([&] {
        const std::uint32_t e0 = tri[(i + 1) % 3], e1 = tri[(i + 2) % 3];
        return "vertex " + facts.vertex(v) + " " + point_text(q.x, q.y) + " lies on the edge (" +
               facts.vertex(std::min(e0, e1)) + " " + facts.vertex(std::max(e0, e1)) + ") of " +
               facts.triangle(t);
      });
    });
  }
}

}  // namespace meshstep::check_detail
