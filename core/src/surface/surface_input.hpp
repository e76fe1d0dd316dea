// What bisection and flips on a 3D surface share: the check of their input, the rotation
// that names a triangle from its smallest vertex id, and the measures they report.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/io/surface_io.hpp"
#include "surface_geometry.hpp"

namespace meshstep::surface::detail {

using Triangle = std::array<std::uint32_t, 3>;

// Refuses, naming `who` ("surface bisection"), anything but a manifold surface whose
// triangles agree on their orientation (borders allowed), coordinates that are not finite,
// and more triangles than 32-bit corner-edge numbers (3 a triangle) can count.
inline void check_surface_input(const io::Surface& in, const std::string& who) {
  if (in.triangles.size() > std::numeric_limits<std::uint32_t>::max() / 3)
    throw InputError(who + ": too many triangles (" + std::to_string(in.triangles.size()) + ")");
  for (std::size_t v = 0; v < in.vertices.size(); ++v) {
    const Point3& p = in.vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(who + ": vertex " + std::to_string(v) + " has a coordinate that is not finite");
  }
  const io::SurfaceReport r = io::report_surface(in);  // throws for an index past the end
  if (r.degenerate_triangles > 0 || r.duplicate_triangles > 0 || r.non_manifold_edges > 0 ||
      r.inconsistent_edges > 0) {
    // Vertices of no triangle are harmless: they are carried through.
    io::SurfaceReport problems = r;
    problems.unused_vertices = 0;
    throw InputError(who + " needs a manifold surface with consistently oriented triangles; this one is " +
                     io::describe(problems));
  }
}

// The triangle from its smallest vertex id, keeping its orientation.
inline Triangle from_smallest(const Triangle& t) {
  if (t[1] < t[0] && t[1] < t[2]) return {t[1], t[2], t[0]};
  if (t[2] < t[0] && t[2] < t[1]) return {t[2], t[0], t[1]};
  return t;
}

struct SurfaceMeasures {
  double smallest_angle_deg = 0.0;
  double area = 0.0;
};

// The smallest angle and the area of a triangle list, each triangle measured from its
// smallest vertex id (so that the figures do not depend on how the triangles are listed).
inline SurfaceMeasures measure_surface(const std::vector<Point3>& points, const std::vector<Triangle>& triangles) {
  if (triangles.empty()) return {};
  double smallest = 180.0;
  CompensatedSum area;
  for (const Triangle& t : triangles) {
    const Triangle s = from_smallest(t);
    const Point3 &a = points[s[0]], &b = points[s[1]], &c = points[s[2]];
    smallest = std::min(smallest, smallest_angle_deg(a, b, c));
    area.add(detail::area(a, b, c));
  }
  return {smallest, area.value()};
}

}  // namespace meshstep::surface::detail
