// Small questions both refinement loops (Delaunay refinement and Lepp bisection) ask of the
// mesh, answered the same way for both so that their runs stay comparable.
#pragma once

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "meshstep/geometry/magnitudes.hpp"
#include "meshstep/geometry/point.hpp"
#include "meshstep/geometry/predicates.hpp"
#include "meshstep/mesh/concept.hpp"
#include "meshstep/refine/quality.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/replay/event.hpp"
#include "scaled_criteria.hpp"

namespace meshstep::detail {

// The half-edge of f that leaves its smallest vertex id: a face named by its vertices, not
// by where a data structure stored it.
template <TriangleMesh Mesh>
HalfEdge first_edge(const Mesh& mesh, FaceId f) {
  HalfEdge h = mesh.half_edge(f);
  const HalfEdge n = mesh.next(h), p = mesh.prev(h);
  if (mesh.origin(n) < mesh.origin(h)) h = n;
  if (mesh.origin(p) < mesh.origin(h)) h = p;
  return h;
}

// Does face f still hold the triangle (a, b, c) (a its smallest vertex)?
template <TriangleMesh Mesh>
bool holds_triangle(const Mesh& mesh, FaceId f, VertexId a, VertexId b, VertexId c) {
  if (!mesh.is_live(f)) return false;
  const HalfEdge h = first_edge(mesh, f);
  return mesh.origin(h) == a && mesh.dest(h) == b && mesh.apex(h) == c;
}

// Would splitting the edge of h at p (a rounded point on it) leave every triangle on both
// sides counterclockwise, exactly, and the mesh within what it covered? Not for an edge a few
// ulps long, nor for a boundary edge and a point beyond its line (see inside_boundary).
template <TriangleMesh Mesh>
bool splits_cleanly(const Mesh& mesh, const std::vector<Point>& points, HalfEdge h, const Point& p) {
  const Point &a = points[mesh.origin(h)], &b = points[mesh.dest(h)];
  if (p == a || p == b) return false;
  const Point& c = points[mesh.apex(h)];
  if (orient2d(a, p, c) <= 0.0 || orient2d(p, b, c) <= 0.0) return false;
  const HalfEdge t = mesh.twin(h);
  if (t == kNone) return orient2d(a, b, p) >= 0.0;
  const Point& d = points[mesh.apex(t)];
  return orient2d(b, p, d) > 0.0 && orient2d(p, a, d) > 0.0;
}

// The point p at which to split the edge of h, moved onto the mesh's side of its line when h
// is a boundary edge (no triangle beyond it). Rounded a hair beyond the line, p would carry
// the boundary out over the sliver (a, p, b), and with it any vertex the mesh left outside
// there: an input vertex an ulp beyond a segment would end inside a triangle (issue 31,
// fuzz_pipeline). It moves an ulp at a time towards the inside, which the rounding of a
// midpoint or a shell point undoes in a step or two. An interior edge's split stays within
// its two triangles (splits_cleanly): p is returned as it is.
template <TriangleMesh Mesh>
Point inside_boundary(const Mesh& mesh, const std::vector<Point>& points, HalfEdge h, Point p) {
  if (mesh.twin(h) != kNone) return p;
  const Point &a = points[mesh.origin(h)], &b = points[mesh.dest(h)];
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // The inside is to the left of a->b: along (a.y - b.y, b.x - a.x).
  const double inward_x = a.y - b.y, inward_y = b.x - a.x;
  for (int step = 0; step < 8 && orient2d(a, b, p) < 0.0; ++step) {
    if (inward_x != 0.0) p.x = std::nextafter(p.x, inward_x > 0.0 ? kInf : -kInf);
    if (inward_y != 0.0) p.y = std::nextafter(p.y, inward_y > 0.0 ? kInf : -kInf);
  }
  return p;
}

// The criteria one by one: does the triangle (a, b, c) of shape s miss the bound? Both
// refinement loops test through these, and so does the record of what a step fixes
// (record_failed_criteria), so that the two cannot disagree.
inline bool misses_min_angle(const ScaledCriteria& criteria, const quality::Shape& s) {
  return s.sin2_min_angle() < criteria.sin2_min_angle;
}
inline bool misses_max_angle(const ScaledCriteria& criteria, const quality::Shape& s) {
  return s.cos_max_angle() < criteria.cos_max_angle;
}
inline bool misses_max_aspect(const ScaledCriteria& criteria, const quality::Shape& s) {
  return criteria.max_aspect > 0.0 && s.aspect() > criteria.max_aspect;
}
inline bool misses_max_area(const ScaledCriteria& criteria, const quality::Shape& s) {
  return criteria.max_area > 0.0 && s.area > criteria.max_area;
}
// The area bound of the triangle's own (its region's, the caller's).
inline bool misses_local_max_area(const ScaledCriteria& criteria, const quality::Shape& s, const Point& a,
                                  const Point& b, const Point& c) {
  if (!criteria.max_area_for) return false;
  const double bound = criteria.max_area_for(a, b, c);
  return bound > 0.0 && s.area > bound;
}
// The size function at the centroid bounds the longest edge.
inline bool misses_size(const ScaledCriteria& criteria, const quality::Shape& s, const Point& a, const Point& b,
                        const Point& c) {
  if (!criteria.size) return false;
  const Point centroid{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
  const double l = criteria.size(centroid);
  return l > 0.0 && s.longest2 > l * l;
}

// Is the triangle (a, b, c)'s centroid in the run's region (always, without one)? The
// centroid is rounded in the scaled coordinates and scaled back by a power of two, exactly:
// it is the same double as the centroid of the caller's own coordinates.
[[gnu::always_inline]] inline bool in_region(const ScaledCriteria& criteria, const Point& a, const Point& b,
                                             const Point& c) {
  if (!criteria.region) return true;
  const Point centroid{(a.x + b.x + c.x) / 3.0 * criteria.unscale, (a.y + b.y + c.y) / 3.0 * criteria.unscale};
  return criteria.region->contains(centroid);
}

// Does the triangle (a, b, c) of shape s fail a size criterion: the area bound, its own area
// bound (region, caller), or the size function (longest edge) at its centroid?
inline bool too_large(const ScaledCriteria& criteria, const quality::Shape& s, const Point& a, const Point& b,
                      const Point& c) {
  return misses_max_area(criteria, s) || misses_local_max_area(criteria, s, a, b, c) ||
         misses_size(criteria, s, a, b, c);
}

// Records a failed criterion_test for every bound the triangle (a, b, c) misses, with what
// was measured (in scaled coordinates: the recorder unscales). Recording only: the loops
// themselves stop at the first bound missed and measure nothing they do not compare.
template <class Rec>
void record_failed_criteria(Rec& rec, const ScaledCriteria& criteria, const std::vector<Point>& points, VertexId a,
                            VertexId b, VertexId c) {
  using replay::Criterion;
  const Point &pa = points[a], &pb = points[b], &pc = points[c];
  const quality::Shape s = quality::shape(pa, pb, pc);
  const auto failed = [&](Criterion criterion, double measured) {
    rec.criterion_test(criterion, false, a, b, c, measured);
  };
  if (misses_min_angle(criteria, s)) failed(Criterion::min_angle, s.min_angle_deg());
  if (misses_max_angle(criteria, s)) failed(Criterion::max_angle, s.max_angle_deg());
  if (misses_max_aspect(criteria, s)) failed(Criterion::max_aspect, s.aspect());
  if (misses_max_area(criteria, s)) failed(Criterion::max_area, s.area);
  if (misses_local_max_area(criteria, s, pa, pb, pc)) failed(Criterion::local_max_area, s.area);
  if (misses_size(criteria, s, pa, pb, pc)) failed(Criterion::size, std::sqrt(s.longest2));
}

// Records a Lepp path: its faces as vertex triples (into `scratch`), its terminal edge e and
// how many terminal triangles it has.
template <class Rec, TriangleMesh Mesh>
void record_lepp_path(Rec& rec, const Mesh& mesh, const std::vector<FaceId>& path, HalfEdge e,
                      std::uint32_t terminal_triangles, std::vector<VertexId>& scratch) {
  scratch.clear();
  for (const FaceId g : path) {
    const HalfEdge h = mesh.half_edge(g);
    scratch.insert(scratch.end(), {mesh.origin(h), mesh.dest(h), mesh.apex(h)});
  }
  rec.lepp_path(mesh.origin(e), mesh.dest(e), terminal_triangles, scratch);
}

// Has the run reached its Steiner-vertex or triangle cap?
template <TriangleMesh Mesh>
bool reached_cap(const ScaledCriteria& criteria, std::size_t steiner, const Mesh& mesh) {
  return (criteria.max_steiner && steiner >= criteria.max_steiner) ||
         (criteria.max_triangles && mesh.face_count() >= criteria.max_triangles);
}

// Calls the progress callback about once a second, looking at the clock every `every` rounds.
class ProgressClock {
 public:
  ProgressClock(const std::function<void(const RefineProgress&)>& progress, std::uint64_t every)
      : progress_(progress), every_(every) {}

  template <class Make>
  void tick(std::uint64_t round, Make make_progress) {
    if (!progress_ || round % every_ != 0) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::seconds(1)) return;
    last_ = now;
    RefineProgress p = make_progress();
    p.seconds = std::chrono::duration<double>(now - started_).count();
    progress_(p);
  }

 private:
  const std::function<void(const RefineProgress&)>& progress_;
  std::uint64_t every_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now(), last_ = started_;
};

}  // namespace meshstep::detail
