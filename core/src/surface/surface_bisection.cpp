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
#include "surface_input.hpp"
#include "surface_loader.hpp"

namespace meshstep::surface {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

void check_bound(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value))
    throw InputError(std::string("surface bisection: ") + name + " must be a finite number >= 0, not " +
                     std::to_string(value));
}

void check_input(const io::Surface& in, const BisectionOptions& options) {
  check_bound(options.max_edge, "the largest edge length");
  check_bound(options.max_area, "the largest area");
  detail::check_surface_input(in, "surface bisection");
}

// Each triangle from its smallest vertex id, keeping its orientation.
Triangle from_smallest(VertexId a, VertexId b, VertexId c) { return detail::from_smallest(Triangle{a, b, c}); }

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
  const detail::SurfaceMeasures before = detail::measure_surface(in.vertices, in.triangles);
  io::Surface out = options.data_structure == DataStructure::dcel ? bisect_with<Dcel>(in, options, r)
                                                                  : bisect_with<Tds>(in, options, r);
  const detail::SurfaceMeasures after = detail::measure_surface(out.vertices, out.triangles);
  r.triangles = out.triangles.size();
  r.smallest_angle_before_deg = before.smallest_angle_deg;
  r.smallest_angle_after_deg = after.smallest_angle_deg;
  r.area_before = before.area;
  r.area_after = after.area;
  if (report != nullptr) *report = r;
  return out;
}

}  // namespace meshstep::surface
