// Delaunay refinement: a PSLG in, a quality mesh out.
//
// A refinement algorithm is a combination of parts: the criteria a triangle must meet, the
// point selected to fix a triangle that does not, and the insertion that adds the point.
// refine() runs a named combination (refine/registry.hpp) or any free one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/pslg/pslg.hpp"
#include "meshstep/refine/region.hpp"

namespace meshstep {

// Where a bad triangle asks for its new vertex.
enum class Selection {
  circumcenter,  // Ruppert / Chew
  offcenter,     // Ungor: on the bisector of the shortest edge, no farther than needed
  lepp_midpoint, // Rivara: the midpoint of the terminal edge of the triangle's Lepp
  lepp_centroid, // Rivara et al.: the centroid of the two terminal triangles of the Lepp
  longest_edge_midpoint,  // the midpoint of the bad triangle's own longest edge
};

// How a refinement adds its points: Delaunay insertion (the triangulation's flips or cavity,
// TriangulateOptions::insertion) of the selected point, or Lepp longest-edge bisection
// (Rivara; not Delaunay, size criteria only, the selection does not apply).
enum class RefineInsertion { delaunay, bisection };

// Which bad triangle next: the one with the shortest shortest edge (Triangle's order; it
// keeps the mesh graded at high angle bounds, where worst-angle-first refines whole open
// areas needlessly: 197k Steiner points against 16k on earcut_water at 34 degrees), the one
// with the smallest angle, or first come first served.
enum class RefineOrder { smallest_first, worst_first, fifo };

// Which points encroach on a segment: those inside its diametral circle, or only those
// inside its diametral lens, seeing the segment at 180 - 2 theta degrees or more, theta
// the angle bound (Shewchuk; 120 degrees at a 30-degree bound): fewer splits.
enum class Encroachment { circle, lens };

// The selection's own rule, from its record (refine/registry.hpp, which says why).
Encroachment default_encroachment(Selection selection);

// When a subsegment is split away from corners, the free Steiner vertices (not on a
// segment) that face its two halves from inside its diametral circle are deleted, one after
// the other as each becomes the apex of a triangle on a half (Chew's rule; Triangle does it
// by default, on the subsegment before the split): they would crowd the new subsegments. On the Triangle corpus it
// takes the largest ratio to Triangle's points from 1.27 to 1.22. Under an area or size
// bound the bound puts them back: 33.6k deletions and as many insertions again on A.poly at
// 1e-7, for the same number of points in 1.43 times the time.
enum class FreeVertexDeletion : std::uint8_t {
  unless_sized,  // the default: deleted unless an area or size bound is set
  always,
  never,
};

// Which segments refinement may split (Triangle's -Y and -YY): every one (the default), only
// those with triangles on both sides (interior: the domain's boundary, holes' included, is
// never split), or none. A segment that may not be split stays as the input has it: the mesh
// is then constrained Delaunay, not conforming, and a bad triangle whose point would encroach
// on such a segment (or lie beyond it, outside the domain) is left as it is, so that the
// bounds may be missed near it (RefineReport::kept_segment_refusals says how often).
enum class SegmentSplits : std::uint8_t { all, interior, none };

// Stopping criteria: a triangle is bad when it fails any bound that is set (all-of).
struct RefineCriteria {
  double min_angle_deg = 0.0;    // 0: none
  double max_angle_deg = 180.0;  // 180: none
  double max_aspect = 0.0;       // longest edge / shortest altitude (quality::Shape::aspect); 0: none
  double max_area = 0.0;         // 0: none
  // Largest edge length wanted near a point (a size function); empty: none.
  std::function<double(const Point&)> size;
  // Largest area wanted for the counterclockwise triangle (a, b, c) (<= 0: none); empty:
  // none. Re-refinement fills it from the old mesh's .area.
  std::function<double(const Point& a, const Point& b, const Point& c)> max_area_for;
  std::size_t max_triangles = 0;  // stop once the mesh has this many; 0: none
  std::size_t max_steiner = 0;    // stop after inserting this many vertices; 0: none
};

// Where a long run stands (RefineOptions::progress).
struct RefineProgress {
  std::size_t steiner_vertices = 0;
  std::size_t triangles = 0;
  std::size_t queued = 0;  // bad triangles and suspect subsegments waiting
  double seconds = 0.0;    // since refinement began
};

// One phase of a refinement run in phases (the combined-criteria method: an aspect-ratio
// phase, then a min-angle phase).
struct RefinePhase {
  std::string name;  // for the report and the progress output
  RefineCriteria criteria;
};

struct RefineOptions {
  std::string algorithm = "circumcenter";  // for the record and the report
  Selection selection = Selection::circumcenter;
  RefineCriteria criteria;
  // When not empty, the run goes through these in order, each to its own criteria, on the
  // mesh the phase before left (`criteria` is then unused).
  std::vector<RefinePhase> phases;
  RefineInsertion insertion = RefineInsertion::delaunay;
  RefineOrder order = RefineOrder::smallest_first;  // bisection: largest area first unless FIFO
  Encroachment encroachment = Encroachment::lens;
  // Improvement + refinement (Coll et al. 2008): after refining, remove every free Steiner
  // vertex (not on a segment) whose removal raises the smallest angle round it and leaves
  // triangles that meet the criteria. Delaunay insertion only.
  bool improve = false;
  // Free Steiner vertices that face a subsegment about to be split away from corners,
  // inside its diametral circle (FreeVertexDeletion). Delaunay insertion only: bisection
  // ignores it.
  FreeVertexDeletion delete_free = FreeVertexDeletion::unless_sized;
  // Which segments may be split (SegmentSplits). Delaunay insertion only: bisection must
  // split the terminal edge it reaches, and refine() refuses it with anything but all.
  SegmentSplits segment_splits = SegmentSplits::all;
  // Refine each region of the input to its own maximum area (Region::max_area, from the
  // .poly's regional attributes), besides the global criteria.
  bool regional_max_area = true;
  // When set, only triangles whose centroid lies in the region are tested against the
  // criteria (all of them: angles, aspect, areas, sizes, in every phase); the rest are left
  // as they are unless the algorithm's own rules reach them (a segment split, a Lepp path,
  // a Delaunay flip). The centroid is the rounded ((a + b + c) / 3) of the triangle's
  // coordinates, and its place in the region is decided exactly (region.hpp).
  std::optional<RefineRegion> region;
  TriangulateOptions triangulate;  // data structure, insertion, convex hull, recording
  // Called about once a second during a long refinement (not at all for a short one).
  std::function<void(const RefineProgress&)> progress;
};

struct RefineReport {
  TriangulateReport triangulation;
  std::size_t steiner_vertices = 0;      // inserted by refinement (segment splits included)
  std::size_t segment_splits = 0;
  std::size_t triangles_split = 0;       // bad triangles fixed by inserting their point
  std::size_t rejected_points = 0;       // selected points that encroached (a segment split instead)
  std::size_t skipped_small_angle = 0;   // bad triangles left alone by rule (quality::cannot_improve)
  std::size_t unsplittable_segments = 0; // splits refused: the subsegment is a few ulps long
                                         // (or its point would leave the exact range)
  std::size_t points_out_of_range = 0;   // bad triangles left: their point would have a
                                         // coordinate below 2^-140 of the largest
  std::size_t kept_segment_refusals = 0; // bad triangles left: their point would encroach on (or lie
                                         // beyond) a segment that may not be split (segment_splits)
  std::size_t removed_vertices = 0;      // Steiner vertices removed again (improvement, deletion near
                                         // split segments); not in steiner_vertices
  bool stopped_by_cap = false;           // max_triangles or max_steiner reached
  // After the run: triangles that miss the bounds, and how many of them touch a small
  // input angle (a vertex where two segments meet at less than 60 degrees, or a vertex on
  // a segment that ends at one).
  std::size_t below_min_angle = 0;
  std::size_t bad_triangles = 0;
  std::size_t bad_near_small_input_angle = 0;
  bool bounds_met = false;
  // Triangles with their centroid in RefineOptions::region after the run (all of them
  // without a region): 0 says the region lies within triangles whose centroids are outside
  // it, and nothing was refined.
  std::size_t region_triangles = 0;
  double triangulate_ms = 0.0, refine_ms = 0.0;
  // Per phase (one, named "refine", for a run without phases): its name and milliseconds.
  std::vector<std::pair<std::string, double>> phase_ms;
};

// What is wrong with the criteria's ranges ("minimum angle 70 is out of range (0 to below
// 60 degrees)"), or "" when nothing is: refine() refuses the same, but a command asks first,
// so that a usage error comes before any reading, warning or progress.
std::string criteria_problem(const RefineCriteria& criteria);

// Throws InputError like triangulate(), and for criteria out of range.
TriMesh refine(Pslg input, const RefineOptions& options, RefineReport* report = nullptr);

// Re-refinement of an existing mesh, as Triangle's -r: its vertices (kept first, in order),
// its segments and boundary edges as segments (boundary edges get marker 1), its holes found
// again from its triangles; each old triangle's maximum area (mesh.triangle_max_area, read
// from PREFIX.area) bounds the new triangles whose centroid lies in it, together with
// options.criteria. Throws InputError for a mesh with no triangles.
TriMesh refine_mesh(const TriMesh& mesh, RefineOptions options, RefineReport* report = nullptr);

// A chain of refinements on one mesh, in one run (a recipe's operations): the input is
// triangulated once, with the first operation's triangulation options (data structure,
// insertion, and the log it records to), then each operation's algorithm runs in turn on
// the mesh the one before left, starting from the boundary it left (each subsegment a
// segment), and records its phases into the same log. One report per operation (the same
// count): its own counts, and its own assessment of the mesh at its end; the first also
// holds the triangulation's. `before`, when set, is called with each operation's index as
// it begins. Throws as refine() does, for any operation's criteria, before any work.
TriMesh refine_chain(Pslg input, std::span<const RefineOptions> operations, std::span<RefineReport> reports,
                     const std::function<void(std::size_t)>& before = {});
// The same on an existing mesh, as refine_mesh (its .area bounds the first operation).
TriMesh refine_mesh_chain(const TriMesh& mesh, std::vector<RefineOptions> operations,
                          std::span<RefineReport> reports, const std::function<void(std::size_t)>& before = {});

// The run's report from refine_chain's reports, one per operation: the counts and the
// times summed (the first report holds the triangulation's), the phases of the operations
// after the first named after their operation ("2:refine"), and the assessment of the mesh
// at the end (bounds met, triangles left bad, the region's triangles, a cap reached) the
// last operation's, since it is the mesh the run leaves. `meshstep run` and the Python
// module report a chain with it. An empty span gives an empty report.
RefineReport combined_report(std::span<const RefineReport> reports);

// The angle apb from which a point p encroaches on segment ab under Encroachment::lens:
// 180 - 2 theta for the angle bound theta, no more than the largest angle the other shape
// bounds allow; 90 (the diametral circle) without an angle bound, and at least 90.
double lens_angle_deg(const RefineCriteria& criteria);

const char* to_string(Selection s);
const char* to_string(RefineOrder o);
const char* to_string(RefineInsertion i);
const char* to_string(SegmentSplits s);  // "all", "interior", "none"

}  // namespace meshstep
