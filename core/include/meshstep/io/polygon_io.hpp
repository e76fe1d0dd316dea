// Polygons from GIS files as PSLGs to mesh: GeoJSON (RFC 7946) and WKT (OGC simple
// features). Real coastlines, lakes and parcels come this way.
//
// Every ring becomes a closed chain of segments (its closing vertex, equal to the first, is
// not repeated). Holes are holes: each region the rings enclose an even number of times
// (a polygon's hole, or a pond on an island in a lake) gets a hole point strictly inside
// it, found in a triangulation of the rings themselves (pslg/ring_holes.hpp), not at a
// centroid that a concave hole may not contain. Segment markers: 1 on a shell, 2 on a hole.
// Vertices equal in both coordinates are one vertex.
//
// Reading is strict: a problem is an InputError whose what() reads "FILE:LINE: message"
// (LINE 1-based, of the offending token), never a crash. A ring with fewer than three
// distinct vertices is an error. Coordinates past the second (z, m) are ignored.
#pragma once

#include <string>
#include <vector>

#include "meshstep/pslg/pslg.hpp"

namespace meshstep::io {

// Polygon, MultiPolygon, GeometryCollection, Feature or FeatureCollection; other geometry
// types (points, lines) inside a collection are skipped with a warning, and a file with no
// polygon at all is an error.
Pslg read_geojson(const std::string& path, std::vector<std::string>* warnings = nullptr);

// POLYGON or MULTIPOLYGON (also with Z or M, and SRID=N; prefixes), any case, one or more
// geometries in the file; EMPTY ones are skipped.
Pslg read_wkt(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace meshstep::io
