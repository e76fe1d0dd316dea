// Edge flips on a 3D triangle surface, to raise its smallest angles where the surface is
// flat enough for a flip not to change it much (the seed's FlipDelaunay3DSurface, for
// surfaces).
//
// Two triangles abc and bad that share the edge ab become adc and dbc (the edge cd instead)
// when all of these hold:
//   - their normals differ by at most max_dihedral_deg (0: the two lie in one plane, and the
//     flip changes neither the surface nor its area);
//   - the new triangles face the way the old ones did (the quadrilateral acbd is convex
//     seen along the pair's mean normal) and are not flat;
//   - c and d are not joined already (the flip would make an edge of four triangles);
//   - the smallest of the new pair's six angles is larger than the smallest of the old
//     pair's.
// Each flip raises the pair's smallest angle, so the sorted list of the surface's angles
// grows with every flip and the process ends; the surface's smallest angle never falls.
// Edges are tried in the order of their vertex ids, and again when a flip changes a
// triangle beside them, until none is flipped: the result depends on the geometry and the
// numbering only, not on the order of the triangle list nor on the data structure. Angles
// and normals are measured in 3D, each triangle from its smallest vertex id. The flips are
// made in a mesh structure (either) that the surface is loaded into; an edge that the
// loading left as a seam (its two sides built apart: one for a sphere, the cuts of a torus,
// surface_loader.hpp) is not flipped.
#pragma once

#include <cstddef>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/surface_io.hpp"

namespace meshstep::surface {

struct FlipOptions {
  double max_dihedral_deg = 0.0;  // 0 .. 180
  DataStructure data_structure = DataStructure::tds;
  // Record the run into this replay log (the loading, then a flip_3d step per flip); null:
  // not recorded.
  replay::EventSink* record = nullptr;
};

struct FlipReport {
  std::size_t flips = 0;
  double largest_dihedral_flipped_deg = 0.0;  // of the pairs flipped
  double smallest_angle_before_deg = 0.0, smallest_angle_after_deg = 0.0;
  double area_before = 0.0, area_after = 0.0;
};

// The surface with its triangles flipped: the same vertices, the triangles each listed from
// its smallest vertex id, sorted. Throws InputError for a bound outside 0..180 and for an
// input that is not a manifold surface with consistently oriented triangles (borders
// allowed), as bisect_surface does.
io::Surface flip_surface(const io::Surface& in, const FlipOptions& options, FlipReport* report = nullptr);

}  // namespace meshstep::surface
