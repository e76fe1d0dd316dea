// Lepp longest-edge bisection (Rivara): refinement to an area bound or a size function that
// keeps every triangle's shape, not Delaunay.
//
// For a target triangle t, while t exists: follow Lepp(t) to its terminal edge and bisect
// the terminal triangles there (join the edge's midpoint to their opposite vertices; one
// triangle on the boundary). Each bisection cuts a triangle across its longest edge, so the
// mesh stays conforming after every step and no angle falls below half the smallest angle of
// the starting mesh. Segments do not stop a path: splitting one at its midpoint keeps it
// covered (its two halves stay constrained), and stopping there would cut the triangle
// across the segment through an edge that is not its longest.
//
// Bisection cannot raise angles, so the only criteria are size criteria (area, size
// function) and the caps. The targets are taken largest first or in FIFO order; each step is
// one bisection, recorded with its Lepp path.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <queue>
#include <unordered_map>
#include <vector>

#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/geometry/predicates.hpp"
#include "meshstep/refine/lepp.hpp"
#include "meshstep/refine/quality.hpp"
#include "meshstep/refine/refine.hpp"
#include "mesh_queries.hpp"
#include "scaled_criteria.hpp"

namespace meshstep::detail {

template <TriangleMesh Mesh, class Rec>
class LeppBisector {
 public:
  // The criteria come with set_criteria(), before each run().
  LeppBisector(Triangulation<Mesh, Rec>& tri, const std::vector<Segment>& boundary, std::size_t input_count,
               const RefineOptions& options)
      : tri_(tri), mesh_(tri.mesh()), input_count_(input_count), options_(options),
        exact_range_(std::span<const Point>(tri.points()).first(input_count)) {
    for (const Segment& s : boundary) markers_[edge_tie_key(s.a, s.b)] = s.marker;
  }

  // The criteria of the next run() (a run in phases changes them between runs).
  void set_criteria(const ScaledCriteria& criteria) { criteria_ = criteria; }

  void run(RefineReport& report) {
    Rec& rec = tri_.recorder();
    clear_queues();  // what a capped phase left: the next phase checks every face again
    rec.phase_begin(replay::Phase::refine);
    // Faces are checked in an order of the mesh's own (their vertex ids), never of storage
    // slots, so that FIFO runs alike on every data structure.
    std::vector<FaceId> faces;
    for (FaceId f = 0; f < mesh_.face_capacity(); ++f)
      if (mesh_.is_live(f)) faces.push_back(f);
    check_in_order(faces);
    ProgressClock clock(options_.progress, 1024);
    Target t;
    for (std::uint64_t round = 1; !capped() && pop(t); ++round) {
      clock.tick(round, [&] { return RefineProgress{tri_.points().size() - input_count_, mesh_.face_count(), queued()}; });
      // Bisect along the path until the target itself is cut (or a cap or the precision
      // floor stops it).
      while (still_there(t) && !capped())
        if (!bisect_terminal_edge(t)) break;
    }
    rec.phase_end(replay::Phase::refine);
    report.stopped_by_cap = capped();
    report.unsplittable_segments = unsplittable_;
    report.segment_splits = segment_splits_;
    report.triangles_split = bisections_;
    assess(report);
  }

  // The boundary after the run: every subsegment with its segment's marker.
  std::vector<Segment> boundary() const {
    std::vector<Segment> out;
    out.reserve(markers_.size());
    for (const auto& [k, marker] : markers_)
      out.push_back({static_cast<std::uint32_t>(k >> 32), static_cast<std::uint32_t>(k & 0xFFFFFFFFu), marker});
    return out;
  }

 private:
  // A target triangle: its face and its vertices (from the smallest id), to tell whether
  // the face still holds it; its area orders the queue.
  struct Target {
    double area;
    FaceId face;
    VertexId a, b, c;
    bool operator<(const Target& o) const {
      if (area != o.area) return area < o.area;
      return std::array{a, b, c} > std::array{o.a, o.b, o.c};
    }
  };

  HalfEdge first_edge(FaceId f) const { return detail::first_edge(mesh_, f); }
  const Point& point(VertexId v) const { return tri_.point(v); }

  std::array<VertexId, 3> vertices(FaceId f) const {
    const HalfEdge h = first_edge(f);
    return {mesh_.origin(h), mesh_.dest(h), mesh_.apex(h)};
  }

  void check_in_order(std::vector<FaceId>& faces) {
    std::sort(faces.begin(), faces.end(), [&](FaceId f, FaceId g) { return vertices(f) < vertices(g); });
    for (const FaceId f : faces) check(f);
  }

  void check(FaceId f) {
    const HalfEdge h = first_edge(f);
    const VertexId a = mesh_.origin(h), b = mesh_.dest(h), c = mesh_.apex(h);
    const quality::Shape s = quality::shape(point(a), point(b), point(c));
    if (!too_large(criteria_, s, point(a), point(b), point(c))) return;
    if (!in_region(criteria_, point(a), point(b), point(c))) return;  // after the bound: cheaper first
    const Target t{s.area, f, a, b, c};
    if (options_.order == RefineOrder::fifo) fifo_.push_back(t);
    else largest_.push(t);
  }

  void clear_queues() {
    largest_ = {};
    fifo_.clear();
  }

  bool pop(Target& t) {
    if (options_.order == RefineOrder::fifo) {
      if (fifo_.empty()) return false;
      t = fifo_.front();
      fifo_.pop_front();
      return true;
    }
    if (largest_.empty()) return false;
    t = largest_.top();
    largest_.pop();
    return true;
  }
  std::size_t queued() const { return fifo_.size() + largest_.size(); }

  bool still_there(const Target& t) const { return holds_triangle(mesh_, t.face, t.a, t.b, t.c); }

  bool capped() const { return reached_cap(criteria_, tri_.points().size() - input_count_, mesh_); }

  // One step for target t: the terminal edge of its path, bisected with the triangles on both
  // sides. False, changing nothing, when the rounded midpoint would not leave every triangle
  // counterclockwise (an edge a few ulps long).
  bool bisect_terminal_edge(const Target& t) {
    const HalfEdge e = lepp(mesh_, tri_.points(), t.face, [](HalfEdge) { return false; }, path_);
    const VertexId a = mesh_.origin(e), b = mesh_.dest(e);
    const Point &pa = point(a), &pb = point(b);
    const Point m = detail::inside_boundary(mesh_, tri_.points(), e, {(pa.x + pb.x) / 2.0, (pa.y + pb.y) / 2.0});
    if (!splits_cleanly(e, m) || !exact_range_.holds(m)) {
      ++unsplittable_;
      return false;
    }
    Rec& rec = tri_.recorder();
    rec.step_begin(mesh_, replay::StepKind::bisect, a, b);
    if constexpr (Rec::enabled) {
      record_failed_criteria(rec, criteria_, tri_.points(), t.a, t.b, t.c);  // what the step is for
      record_lepp_path(rec, mesh_, path_, e, mesh_.twin(e) == kNone ? 1 : 2, path_vertices_);
    }
    const auto segment = markers_.find(edge_tie_key(a, b));
    const HalfEdge out = tri_.bisect(m, e);
    const VertexId v = mesh_.origin(out);
    if (segment != markers_.end()) {
      const int marker = segment->second;
      markers_.erase(segment);
      markers_[edge_tie_key(a, v)] = marker;
      markers_[edge_tie_key(v, b)] = marker;
      ++segment_splits_;
    }
    ++bisections_;
    new_faces_.clear();
    tri_.for_each_out_edge(out, [&](HalfEdge h) { new_faces_.push_back(mesh_.face(h)); });
    check_in_order(new_faces_);
    return true;
  }

  bool splits_cleanly(HalfEdge h, const Point& p) const { return detail::splits_cleanly(mesh_, tri_.points(), h, p); }

  void assess(RefineReport& report) const {
    std::size_t bad = 0, in_region_count = 0;
    for (FaceId f = 0; f < mesh_.face_capacity(); ++f) {
      if (!mesh_.is_live(f)) continue;
      const HalfEdge h = first_edge(f);
      const Point &a = point(mesh_.origin(h)), &b = point(mesh_.dest(h)), &c = point(mesh_.apex(h));
      if (!in_region(criteria_, a, b, c)) continue;  // the report speaks of the region
      ++in_region_count;
      bad += too_large(criteria_, quality::shape(a, b, c), a, b, c);
    }
    report.region_triangles = in_region_count;
    report.bad_triangles = bad;
    report.bounds_met = bad == 0;
  }

  Triangulation<Mesh, Rec>& tri_;
  Mesh& mesh_;
  std::size_t input_count_;
  ScaledCriteria criteria_;
  const RefineOptions& options_;
  std::unordered_map<std::uint64_t, int> markers_;  // subsegments and boundary edges
  std::priority_queue<Target> largest_;
  std::deque<Target> fifo_;
  std::vector<FaceId> path_, new_faces_;
  std::vector<VertexId> path_vertices_;
  std::size_t bisections_ = 0, segment_splits_ = 0, unsplittable_ = 0;
  ExactRange exact_range_;
};

}  // namespace meshstep::detail
