// Polygons given as rings (GIS files: GeoJSON, WKT) made into a PSLG to mesh, holes
// included. A GIS polygon says where its holes are only by its rings; meshstep, as
// Triangle, needs a point inside each hole. A hole's centroid need not lie inside it (a
// C-shaped lake), so the hole points come from a triangulation of the rings themselves:
// every region the rings enclose an even number of times is a hole, and its hole point is
// the centroid of one of its triangles, checked strictly inside that triangle with the
// exact orientation predicate. Even-odd is what the simple-features rules make of nested
// rings: a lake (a hole) in a shell is out, an island (a shell) in that lake is in again,
// a pond on the island out. Two polygons that share a border edge (adjacent parcels) do
// not make it a hole: an edge used twice does not change the count.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep {

struct PolygonRing {
  std::vector<Point> points;  // closed or not: a last point equal to the first is dropped
  bool hole = false;          // a polygon's inner ring (marker 2; shells get 1)
  std::size_t line = 0;       // where the ring starts in its file, for messages
};

// Throws InputError(file, ring.line, ...) for a ring with fewer than three distinct
// vertices or a coordinate that is not finite, InputError(file, 0, ...) when there is no
// ring at all. Vertices equal in both coordinates become one; a segment given twice is
// kept once.
Pslg pslg_from_rings(const std::string& file, const std::vector<PolygonRing>& rings,
                     std::vector<std::string>* warnings = nullptr);

}  // namespace meshstep
