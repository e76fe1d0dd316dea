// Stage 7c: a hole point marks a region whose triangles are all removed: the triangle
// holding it is removed and the removal spreads across every edge that is not a segment.
// So no remaining triangle may hold a hole point strictly inside, nor on one of its edges
// that is not a segment (checked when the mesh lists its segments). A hole point on a
// segment is fine: the hole eats only its own side.
#include <algorithm>
#include <array>
#include <cmath>

#include "check/segment_chain.hpp"
#include "check/stages.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep::check_detail {

namespace {

// Is h a hair inside the triangle, next to one of its edges that is a segment (or the
// boundary carving left)? A hole point on the boundary line is fine (the hole eats one
// side), and refinement splits such an edge at a rounded point, which may move the line by
// an ulp across h. Within the segment chains' line_tolerance.
bool near_a_listed_edge(const MeshFacts& facts, const std::array<std::uint32_t, 3>& tri, const Point& h) {
  if (facts.mesh.segments.empty()) return false;
  const auto& p = facts.mesh.points;
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t u = tri[i], v = tri[(i + 1) % 3];
    if (!facts.is_listed(u, v)) continue;
    const double dx = p[v].x - p[u].x, dy = p[v].y - p[u].y, length = std::hypot(dx, dy);
    if (std::fabs(dx * (h.y - p[u].y) - dy * (h.x - p[u].x)) <= line_tolerance(p[u], p[v]) * length) return true;
  }
  return false;
}

}  // namespace

void check_input_holes(MeshFacts& facts, const Pslg& input) {
  if (input.holes.empty()) return;
  const auto& mesh = facts.mesh;
  const BoxTree& tree = facts.triangle_tree();
  for (std::size_t k = 0; k < input.holes.size(); ++k) {
    const Point& h = input.holes[k];
    bool reported = false;
    auto report = [&](std::uint32_t t, const std::string& where) {
      reported = true;
      facts.log.add([&] {
        return "hole " + number(k, input.first_index) + " " + point_text(h.x, h.y) + " lies " +
               where + facts.triangle(t) + ": its region was not removed";
      });
    };
    tree.query([&](const BBox& node) { return reported || !box_contains(node, h); },
               [&](std::uint32_t t) {
                 if (reported) return;
                 const auto& tri = mesh.triangles[t];
                 double o[3];  // o[i]: side of h from the edge opposite corner i
                 for (int i = 0; i < 3; ++i)
                   o[i] = orient2d(mesh.points[tri[(i + 1) % 3]], mesh.points[tri[(i + 2) % 3]], h);
                 if (o[0] < 0.0 || o[1] < 0.0 || o[2] < 0.0) return;
                 const int zeros = (o[0] == 0.0) + (o[1] == 0.0) + (o[2] == 0.0);
                 if (zeros == 0) {
                   if (near_a_listed_edge(facts, tri, h)) return;
                   return report(t, "inside ");
                 }
                 if (zeros != 1 || mesh.segments.empty()) return;  // at a corner, or unknowable
                 const int i = o[0] == 0.0 ? 0 : (o[1] == 0.0 ? 1 : 2);
                 const std::uint32_t u = tri[(i + 1) % 3], v = tri[(i + 2) % 3];
                 if (facts.is_listed(u, v)) return;
                 report(t, "on the edge (" + facts.vertex(std::min(u, v)) + " " +
                               facts.vertex(std::max(u, v)) + "), not a segment, of ");
               });
  }
}

}  // namespace meshstep::check_detail
