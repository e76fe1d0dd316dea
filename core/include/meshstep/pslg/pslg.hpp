// Planar straight line graph: the input of the triangulators and of everything after them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "meshstep/geometry/point.hpp"

namespace meshstep {

struct Segment {
  std::uint32_t a = 0;  // 0-based vertex indices
  std::uint32_t b = 0;
  int marker = 0;
};

// A region point: triangles reachable from it without crossing a segment get the attribute
// and, when max_area > 0, that area bound.
struct Region {
  Point point;
  double attribute = 0.0;
  double max_area = -1.0;  // <= 0: no bound
};

// Parts need not be connected; a .node file gives a PSLG with no segments.
struct Pslg {
  std::vector<Point> points;
  std::size_t attributes_per_vertex = 0;
  std::vector<double> vertex_attributes;  // points.size() * attributes_per_vertex, row-major
  bool has_vertex_markers = false;
  std::vector<int> vertex_markers;  // empty or points.size()
  std::vector<Segment> segments;
  bool has_segment_markers = false;
  std::vector<Point> holes;
  std::vector<Region> regions;
  int first_index = 0;  // numbering of the file it came from (0 or 1), kept for output
};

// Does some region carry a maximum area (a size bound of the input's own)?
inline bool has_regional_area_bounds(const Pslg& pslg) {
  for (const Region& r : pslg.regions)
    if (r.max_area > 0.0) return true;
  return false;
}

}  // namespace meshstep
