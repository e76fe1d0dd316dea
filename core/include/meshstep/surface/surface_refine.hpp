// Refinement of a 3D triangle surface by Rivara's longest-edge bisection with Lepp.
//
// Each step takes a triangle that breaks a size bound, follows its longest-edge
// propagating path (Lepp: across the longest edge, again and again, until the edge is on
// the border or is also the longest edge of the triangle across it) and cuts the one or two
// terminal triangles at the midpoint of that terminal edge, until the triangle itself has
// been cut. Every cut is across a triangle's longest edge, so the mesh never has a hanging
// vertex and no angle falls below half the smallest angle of the input (Rivara's bound:
// each triangle is cut in its own plane). Midpoints lie on their edges (up to the rounding
// of their coordinates), so the surface, its border and its area do not change.
//
// Triangles are taken the most oversized first (to within a factor of 2^(1/4), by buckets),
// so a run stopped by the cap has spent its triangles where they were needed most.
//
// Lengths and areas are measured in 3D. Between edges of equal length the one with the
// smaller pair of vertex ids counts as longer, so the result depends on the geometry and
// the numbering only: both data structures give the same surface, run after run.
#pragma once

#include <cstddef>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/surface_io.hpp"

namespace meshstep::surface {

struct BisectionOptions {
  double max_edge = 0.0;          // every edge at most this long at the end (0: no bound)
  double max_area = 0.0;          // every triangle's area at most this (0: no bound)
  std::size_t max_triangles = 0;  // never more triangles than this (0: no cap)
  // Then flip edges up to this dihedral angle, in the same mesh (surface_flips.hpp; < 0:
  // no flips). A flip that would make a triangle over max_edge or max_area is not taken.
  double flip_dihedral_deg = -1.0;
  DataStructure data_structure = DataStructure::tds;
  // Record the run into this replay log (replay/log_writer.hpp): every vertex with its
  // height (x, y in the plane, z as an elevation event), the loading as the first step,
  // then a bisect step per target. Null: not recorded.
  replay::EventSink* record = nullptr;
};

struct BisectionReport {
  std::size_t bisections = 0;  // edges cut, each adding one vertex
  std::size_t triangles = 0;   // in the output
  double smallest_angle_before_deg = 0.0;
  double smallest_angle_after_deg = 0.0;
  double area_before = 0.0;
  double area_after = 0.0;
  bool capped = false;  // max_triangles stopped the run before every bound was met
  // Triangles of the output over a bound (either), over max_edge, over max_area: none
  // unless the cap stopped the run or doubles could not cut an edge. Flips never add to them.
  std::size_t over_bounds = 0, over_max_edge = 0, over_max_area = 0;
  // Targets left over a bound because the doubles cannot cut their terminal edge: its
  // rounded midpoint is one of its ends, or makes a degenerate triangle with an apex.
  std::size_t too_fine_to_cut = 0;
  std::size_t flips = 0;                      // with flip_dihedral_deg >= 0
  double largest_dihedral_flipped_deg = 0.0;  // of the pairs flipped
};

// The refined surface: the input's vertices first, in their order, then one midpoint per
// bisection in the order they were made; triangles oriented as the input's, each listed
// from its smallest vertex id, sorted. Throws InputError for an input that is not a
// manifold surface (border allowed): degenerate or duplicate triangles, edges of more than
// two triangles, neighbours of opposite orientation, coordinates that are not finite; and
// for a negative or non-finite bound, or a dihedral bound above 180. Vertices of no triangle are kept as they are. A
// triangle whose terminal edge doubles cannot cut (its rounded midpoint is one of its ends,
// or on the line from an end to an apex: a bound near the precision of the coordinates,
// or coordinates of very different magnitudes) is left as it is, and counted.
io::Surface bisect_surface(const io::Surface& in, const BisectionOptions& options,
                           BisectionReport* report = nullptr);

}  // namespace meshstep::surface
