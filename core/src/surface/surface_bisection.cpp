// bisect_surface (surface/surface_refine.hpp): checks the input, loads it into the chosen
// data structure, runs the bisection there and reads the surface back.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/huge_pages.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"
#include "meshstep/surface/surface_refine.hpp"
#include "seam_table.hpp"
#include "surface_bisector.hpp"
#include "surface_geometry.hpp"
#include "surface_loader.hpp"

namespace meshstep::surface {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

void check_bound(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value))
    throw InputError(std::string("surface bisection: ") + name + " must be a finite number >= 0, not " +
                     std::to_string(value));
}

// Refuses what the bisection cannot take: anything but a manifold surface whose triangles
// agree on their orientation (borders allowed), and coordinates that are not finite.
void check_input(const io::Surface& in, const BisectionOptions& options) {
  check_bound(options.max_edge, "the largest edge length");
  check_bound(options.max_area, "the largest area");
  // Corner edges (3 per triangle) are numbered in 32 bits.
  if (in.triangles.size() > std::numeric_limits<std::uint32_t>::max() / 3)
    throw InputError("surface bisection: too many triangles (" + std::to_string(in.triangles.size()) + ")");
  for (std::size_t v = 0; v < in.vertices.size(); ++v) {
    const Point3& p = in.vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError("surface bisection: vertex " + std::to_string(v) + " has a coordinate that is not finite");
  }
  const io::SurfaceReport r = io::report_surface(in);  // throws for an index past the end
  if (r.degenerate_triangles > 0 || r.duplicate_triangles > 0 || r.non_manifold_edges > 0 ||
      r.inconsistent_edges > 0) {
    // Vertices of no triangle are harmless: they are carried through.
    io::SurfaceReport problems = r;
    problems.unused_vertices = 0;
    throw InputError("surface bisection needs a manifold surface with consistently oriented triangles; this one is " +
                     io::describe(problems));
  }
}

// Each triangle from its smallest vertex id, keeping its orientation.
Triangle from_smallest(VertexId a, VertexId b, VertexId c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

struct Measures {
  double smallest_angle_deg = 0.0;
  double area = 0.0;
};

Measures measure(const std::vector<Point3>& points, const std::vector<Triangle>& triangles) {
  if (triangles.empty()) return {};
  double smallest = 180.0;
  detail::CompensatedSum area;
  for (const Triangle& t : triangles) {
    const Triangle c = from_smallest(t[0], t[1], t[2]);
    const Point3 &a = points[c[0]], &b = points[c[1]], &p = points[c[2]];
    smallest = std::min(smallest, detail::smallest_angle_deg(a, b, p));
    area.add(detail::area(a, b, p));
  }
  return {smallest, area.value()};
}

template <TriangleMesh Mesh>
io::Surface bisect_with(const io::Surface& in, const BisectionOptions& options, BisectionReport& report) {
  io::Surface out;
  out.vertices = in.vertices;
  {
    Mesh mesh;
    detail::SeamTable seams;
    detail::load_surface(in, mesh, seams);
    detail::SurfaceBisector<Mesh> bisector(mesh, seams, out.vertices, options);
    bisector.run();
    report.bisections = bisector.bisections();
    report.capped = bisector.capped();
    reserve_huge(out.triangles, mesh.face_count());
    for (FaceId f = 0; f < mesh.face_capacity(); ++f) {
      if (!mesh.is_live(f)) continue;
      const HalfEdge h = mesh.half_edge(f);
      out.triangles.push_back(from_smallest(mesh.origin(h), mesh.dest(h), mesh.apex(h)));
    }
  }
  // Sorted, so that the order says nothing of where a data structure kept its faces.
  std::sort(out.triangles.begin(), out.triangles.end());
  return out;
}

}  // namespace

io::Surface bisect_surface(const io::Surface& in, const BisectionOptions& options, BisectionReport* report) {
  check_input(in, options);
  BisectionReport r;
  const Measures before = measure(in.vertices, in.triangles);
  io::Surface out = options.data_structure == DataStructure::dcel ? bisect_with<Dcel>(in, options, r)
                                                                  : bisect_with<Tds>(in, options, r);
  const Measures after = measure(out.vertices, out.triangles);
  r.triangles = out.triangles.size();
  r.smallest_angle_before_deg = before.smallest_angle_deg;
  r.smallest_angle_after_deg = after.smallest_angle_deg;
  r.area_before = before.area;
  r.area_after = after.area;
  if (report != nullptr) *report = r;
  return out;
}

}  // namespace meshstep::surface
