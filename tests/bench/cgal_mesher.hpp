// CGAL's 2D Delaunay mesher (Mesh_2) as a benchmark peer for meshstep's refinement.
//
// The header does not include CGAL, so that programs comparing against this peer need
// not compile CGAL's templates themselves.
#pragma once

#include <cstddef>

#include "meshstep/pslg/pslg.hpp"

namespace meshstep::bench {

struct CgalMeshResult {
  std::size_t triangles = 0;     // faces with is_in_domain(): the mesh of the domain
  std::size_t vertices = 0;      // every vertex of the triangulation, hole boundaries included
  double min_angle_deg = 0.0;    // smallest angle over the in-domain faces (180 if none)
  double domain_area = 0.0;      // sum of the in-domain face areas
  double construct_seconds = 0;  // wall time: building the constrained Delaunay triangulation
  double refine_seconds = 0;     // wall time: the refine_Delaunay_mesh_2 call alone
};

// Meshes the domain of `input` the way meshstep does: the bounded regions enclosed by the
// segments, minus the regions holding a hole point. Crossing segments are allowed (CGAL
// splits them at approximately computed intersection points).
//
// min_angle_deg: the requested smallest angle, in [0, 60); 0 turns the shape criterion off.
// CGAL guarantees termination only up to about 20.7 degrees.
// max_area: an upper bound on triangle area, like Triangle's -a; <= 0 for none. CGAL bounds
// edge lengths instead; see cgal_mesher.cpp for the conversion. Per-region area bounds
// (input.regions) are ignored.
//
// Throws std::invalid_argument for a bad min_angle_deg.
CgalMeshResult cgal_refine(const Pslg& input, double min_angle_deg, double max_area);

}  // namespace meshstep::bench
