// CGAL's 2D Delaunay mesher (Mesh_2) as a benchmark peer; see cgal_mesher.hpp.
//
// How meshstep's parameters map onto CGAL's (CGAL 5.x, Delaunay_mesh_size_criteria_2):
//
// * Angle. CGAL documents its shape bound as B >= r/l (circumradius over shortest edge),
//   with sin(alpha_min) = 1/(2B), and its constructor takes b with B = sqrt(1/(4b)). So
//   b = 1/(4B^2) = sin^2(alpha_min): the default b = 0.125 (B = sqrt(2)) is 20.7 degrees,
//   the largest bound with a termination guarantee. The implementation agrees: a face is
//   bad when (2 area)^2 / (longest^2 * second longest^2) < b, and that ratio is the squared
//   sine of the angle between the two longest edges, i.e. of the smallest angle.
//
// * Size. CGAL's size bound S limits the length of every edge of a triangle (a face is bad
//   when its longest edge exceeds S); it is not an area. A triangle whose edges are all at
//   most S has area at most that of the equilateral triangle of side S, sqrt(3)/4 S^2, so
//   S = sqrt(4 A / sqrt(3)) is the loosest edge bound that guarantees area <= A. It is
//   stricter than an area bound itself (a long thin triangle of small area is split too),
//   so CGAL's triangles come out smaller on average than those of an area-bounded mesher
//   given the same A: compare triangle counts with that in mind.
#include "cgal_mesher.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

namespace meshstep::bench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using Fb = CGAL::Delaunay_mesh_face_base_2<Kernel>;  // adds the in-domain flag
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// CGAL 5's default intersection tag rejects crossing constraints; meshstep splits them, so
// let CGAL split them too (the crossing points are rounded constructions).
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void build(Cdt& cdt, const Pslg& input) {
  std::vector<Kernel::Point_2> points;
  points.reserve(input.points.size());
  for (const Point& p : input.points) points.emplace_back(p.x, p.y);
  if (input.segments.empty()) {
    cdt.insert(points.begin(), points.end());
    return;
  }
  std::vector<std::pair<std::size_t, std::size_t>> segments;
  segments.reserve(input.segments.size());
  for (const Segment& s : input.segments) segments.emplace_back(s.a, s.b);
  // Inserts every point (isolated ones too) in spatial-sort order, then the constraints.
  cdt.insert_constraints(points.begin(), points.end(), segments.begin(), segments.end());
}

}  // namespace

CgalMeshResult cgal_refine(const Pslg& input, double min_angle_deg, double max_area) {
  if (!(min_angle_deg >= 0.0 && min_angle_deg < 60.0)) {
    throw std::invalid_argument("minimum angle must be in [0, 60) degrees");
  }
  const double sine = std::sin(min_angle_deg * std::numbers::pi / 180.0);
  const double size_bound = max_area > 0.0 ? std::sqrt(4.0 * max_area / std::sqrt(3.0)) : 0.0;
  const Criteria criteria(sine * sine, size_bound);  // size 0: no size bound

  CgalMeshResult result;
  Cdt cdt;
  const Clock::time_point construct_start = Clock::now();
  build(cdt, input);
  result.construct_seconds = seconds_since(construct_start);

  // Seeds with mark = false: the components holding a seed are left out of the domain and
  // every other bounded component is meshed; the unbounded one never is. That is exactly
  // the meaning of hole points. The domain is marked inside this call, so it is timed.
  std::vector<Kernel::Point_2> seeds;
  seeds.reserve(input.holes.size());
  for (const Point& h : input.holes) seeds.emplace_back(h.x, h.y);
  const Clock::time_point refine_start = Clock::now();
  CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), criteria, false);
  result.refine_seconds = seconds_since(refine_start);

  result.vertices = cdt.number_of_vertices();
  double min_angle = std::numbers::pi;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    ++result.triangles;
    const Kernel::Point_2* p[3] = {&f->vertex(0)->point(), &f->vertex(1)->point(),
                                   &f->vertex(2)->point()};
    // The smallest angle sits at the vertex opposite the shortest edge.
    int apex = 0;
    double shortest = HUGE_VAL;
    for (int i = 0; i < 3; ++i) {
      const double len2 = CGAL::squared_distance(*p[(i + 1) % 3], *p[(i + 2) % 3]);
      if (len2 < shortest) {
        shortest = len2;
        apex = i;
      }
    }
    const Kernel::Vector_2 u = *p[(apex + 1) % 3] - *p[apex];
    const Kernel::Vector_2 v = *p[(apex + 2) % 3] - *p[apex];
    const double cross = std::abs(u.x() * v.y() - u.y() * v.x());
    result.domain_area += 0.5 * cross;
    min_angle = std::min(min_angle, std::atan2(cross, u * v));
  }
  result.min_angle_deg = min_angle * 180.0 / std::numbers::pi;
  return result;
}

}  // namespace meshstep::bench
