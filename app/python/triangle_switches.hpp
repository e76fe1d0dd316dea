// The switches of Triangle's command line, as the `triangle` Python package passes them
// ("pq30a0.1e"), read into a value. Only the ones meshstep.triangulate supports are
// accepted; any other letter is refused naming it, never ignored.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace meshstep::python {

struct TriangleSwitches {
  bool pslg = false;                   // p: segments, holes and regions are used
  bool quality = false;                // q[ANGLE]
  std::string min_angle;               // its number as written; empty: Triangle's 20 degrees
  std::string max_area;                // a[AREA] with a number; empty: none
  bool regional_area = false;          // a alone: the regions' (or, with r, the triangles') areas
  bool convex_hull = false;            // c
  bool refine_mesh = false;            // r: refine tri['triangles'] again
  bool edges = false;                  // e
  bool neighbors = false;              // n
  bool conforming = false;             // D: every triangle Delaunay (diametral circles)
  std::optional<std::string> max_steiner;  // S[N]; "" for S alone (no Steiner point)
  bool attributes = false;             // A: triangles get their region's attribute
  int keep_segments = 0;               // Y: 1 keeps the boundary's segments whole, 2 (YY) every segment
};

// Throws std::invalid_argument naming the first switch it does not support, or a number it
// cannot read, with the whole text ("switch 'V' in 'pqV' is not supported ...").
TriangleSwitches parse_triangle_switches(std::string_view text);

}  // namespace meshstep::python
