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
#include "meshstep/replay/recorder.hpp"
#include "meshstep/surface/surface_refine.hpp"
#include "seam_table.hpp"
#include "size_bounds.hpp"
#include "surface_bisector.hpp"
#include "surface_flipper.hpp"
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
  if (!(options.flip_dihedral_deg <= 180.0))
    throw InputError("surface flips: the dihedral bound must be between 0 and 180 degrees, not " +
                     std::to_string(options.flip_dihedral_deg));
  detail::check_surface_input(in, options.max_edge > 0.0 || options.max_area > 0.0 ? "surface bisection"
                                                                                     : "surface flips");
}

// Each triangle from its smallest vertex id, keeping its orientation.
Triangle from_smallest(VertexId a, VertexId b, VertexId c) { return detail::from_smallest(Triangle{a, b, c}); }

template <TriangleMesh Mesh, class Rec>
io::Surface bisect_with(const io::Surface& in, const BisectionOptions& options, BisectionReport& report, Rec rec) {
  io::Surface out;
  out.vertices = in.vertices;
  {
    Mesh mesh;
    detail::SeamTable seams;
    if constexpr (Rec::enabled) {
      // The first step: every vertex (in the plane, with its height), then the surface
      // loaded triangle by triangle.
      rec.step_begin(mesh, replay::StepKind::start);
      for (VertexId v = 0; v < in.vertices.size(); ++v) {
        rec.vertex(v, Point{in.vertices[v].x, in.vertices[v].y});
        rec.elevation(v, in.vertices[v].z);
      }
    }
    detail::load_surface(in, mesh, seams, rec);
    detail::SurfaceBisector<Mesh, Rec> bisector(mesh, seams, out.vertices, options, rec);
    bisector.run();
    if (options.flip_dihedral_deg >= 0.0) {
      FlipReport flips;
      // The flips keep the bounds the bisection met (surface_flipper.hpp).
      const detail::SizeBounds bounds(options.max_edge, options.max_area);
      detail::SurfaceFlipper<Mesh, Rec>(mesh, out.vertices, options.flip_dihedral_deg, bounds, rec).run(flips);
      report.flips = flips.flips;
      report.largest_dihedral_flipped_deg = flips.largest_dihedral_flipped_deg;
    }
    rec.run_end(mesh);
    report.bisections = bisector.bisections();
    report.capped = bisector.capped();
    report.too_fine_to_cut = bisector.too_fine_to_cut();
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
  io::Surface out;
  if (options.record) {
    const replay::Recorder rec(*options.record);
    out = options.data_structure == DataStructure::dcel ? bisect_with<Dcel>(in, options, r, rec)
                                                        : bisect_with<Tds>(in, options, r, rec);
  } else {
    out = options.data_structure == DataStructure::dcel ? bisect_with<Dcel>(in, options, r, replay::NullRecorder{})
                                                        : bisect_with<Tds>(in, options, r, replay::NullRecorder{});
  }
  const detail::SurfaceMeasures after = detail::measure_surface(out.vertices, out.triangles);
  r.triangles = out.triangles.size();
  const detail::SizeBounds bounds(options.max_edge, options.max_area);
  if (bounds.any())
    for (const Triangle& t : out.triangles) {  // each from its smallest id, as the bisection measured it
      const Point3 &a = out.vertices[t[0]], &b = out.vertices[t[1]], &c = out.vertices[t[2]];
      const bool edge_over = bounds.edge_over(a, b, c), area_over = bounds.area_over(a, b, c);
      r.over_max_edge += edge_over;
      r.over_max_area += area_over;
      r.over_bounds += edge_over || area_over;
    }
  r.smallest_angle_before_deg = before.smallest_angle_deg;
  r.smallest_angle_after_deg = after.smallest_angle_deg;
  r.area_before = before.area;
  r.area_after = after.area;
  if (report != nullptr) *report = r;
  return out;
}

}  // namespace meshstep::surface
