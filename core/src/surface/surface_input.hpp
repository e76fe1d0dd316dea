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
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/io/surface_io.hpp"
#include "surface_geometry.hpp"

namespace meshstep::surface::detail {

using Triangle = std::array<std::uint32_t, 3>;

// The surface is measured in doubles (surface_geometry.hpp): an area takes the fourth power
// of coordinate differences, which overflows past 2^255 and leaves nothing of surfaces
// whose every coordinate is below 2^-255. Such a surface was measured as infinite or empty
// and came back unrefined, silently; it is refused, naming the coordinate. (The plane's
// exact path scales by a power of two instead; here the bounds and the log would have to
// follow.)
inline constexpr int kSurfaceHighestExponent = 240, kSurfaceLowestExponent = -240;

inline void check_measurable(const io::Surface& in, const std::string& who) {
  double largest = 0.0;
  std::size_t at = 0;
  for (std::size_t v = 0; v < in.vertices.size(); ++v)
    for (const double c : {in.vertices[v].x, in.vertices[v].y, in.vertices[v].z})
      if (std::fabs(c) > largest) largest = std::fabs(c), at = v;
  if (largest == 0.0) return;
  const int e = std::ilogb(largest);
  if (e >= kSurfaceHighestExponent || e < kSurfaceLowestExponent)
    throw InputError(who + ": vertex " + std::to_string(at) + " has a coordinate of magnitude " +
                     io::shortest_text(largest) + ", and the largest must lie between 2^" +
                     std::to_string(kSurfaceLowestExponent) + " and 2^" + std::to_string(kSurfaceHighestExponent) +
                     " (about 1e-72 to 1e72): lengths and areas in 3D are measured in doubles");
}

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
  check_measurable(in, who);
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
