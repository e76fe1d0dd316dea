// Triangle quality measures and a canonical form of a triangle set, for tests and reports.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep {

struct AngleStats {
  double min_angle_deg = 0.0;  // smallest angle of any triangle
  double max_angle_deg = 0.0;  // largest angle of any triangle
};

// Over all triangles whose indices are in range; 0/0 when there are none.
AngleStats angle_stats(const TriMesh& mesh);

// Angles in degrees, independent of orientation; a corner with a zero-length side has
// angle 0, so a degenerate triangle reports min 0.
double triangle_min_angle_deg(const Point& a, const Point& b, const Point& c);
double triangle_max_angle_deg(const Point& a, const Point& b, const Point& c);

// Each triangle rotated (orientation kept) to start at its smallest index, then the list
// sorted: two meshes over the same vertex numbering have equal results exactly when they
// hold the same set of oriented triangles, whatever order and rotation they list them in.
std::vector<std::array<std::uint32_t, 3>> canonical_triangles(const TriMesh& mesh);

}  // namespace meshstep
