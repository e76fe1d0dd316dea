// The refinement loop of surface bisection (surface_refine.hpp), on any TriangleMesh that
// the loader filled: Rivara's longest-edge bisection driven by Lepp, in 3D.
//
// Targets (triangles over a bound) wait in a bucket queue (target_queue.hpp), the most
// oversized first. For the next target: while it still exists, walk its Lepp to the
// terminal edge and cut the one or two triangles there at the edge's midpoint. A triangle
// in the queue is named by its face and its vertices; when the face no longer holds those
// vertices the triangle was cut meanwhile, and its pieces have been queued on their own.
//
// Seams (seam_table.hpp) are crossed through the table, and cutting one cuts both of its
// sides with the same new vertex. The table holds half-edges, which a split may renumber
// (the Tds rewrites the faces it splits), so after each cut the half-edges of the new faces
// that face no neighbour are written back into it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

#include "meshstep/geometry/collinear3.hpp"
#include "meshstep/geometry/point3.hpp"
#include "meshstep/huge_pages.hpp"
#include "meshstep/mesh/concept.hpp"
#include "meshstep/refine/lepp.hpp"
#include "meshstep/replay/recorder.hpp"
#include "meshstep/surface/surface_refine.hpp"
#include "seam_table.hpp"
#include "size_bounds.hpp"
#include "surface_geometry.hpp"
#include "target_queue.hpp"

namespace meshstep::surface::detail {

// Rec records the run (replay/recorder.hpp): a `bisect` step per target, which names the
// bound it breaks (a failed size or max_area criterion_test, measured in 3D), then for each
// cut the Lepp path, the new vertex with its height (vertex, elevation) and the split(s).
template <TriangleMesh Mesh, class Rec = replay::NullRecorder>
class SurfaceBisector {
 public:
  SurfaceBisector(Mesh& mesh, SeamTable& seams, std::vector<Point3>& points, const BisectionOptions& options,
                  Rec& rec)
      : mesh_(mesh), seams_(seams), points_(points), options_(options), rec_(rec),
        max_edge_squared_(options.max_edge * options.max_edge), bounds_(options.max_edge, options.max_area) {}

  void run() {
    if (options_.max_edge <= 0.0 && options_.max_area <= 0.0) return;
    queue_first_targets();
    rec_.phase_begin(replay::Phase::refine);
    Target t;
    while (!capped_ && targets_.pop(t)) {
      if (!still_there(t)) continue;
      if constexpr (Rec::enabled) record_target(t);
      while (still_there(t))
        if (!bisect_terminal_edge(t.face)) break;
    }
    rec_.phase_end(replay::Phase::refine);
  }

  std::size_t bisections() const { return bisections_; }
  std::size_t too_fine_to_cut() const { return too_fine_to_cut_; }
  bool capped() const { return capped_; }

 private:
  // The half-edges of the tds limit a mesh to 2^31 of them; stop short of it.
  static constexpr std::size_t kMostFaces = (std::size_t{1} << 31) / 3 - 4;

  // The half-edge of f leaving its smallest vertex id: a triangle named by its vertices,
  // not by where or in which rotation a data structure stored it.
  HalfEdge first_edge(FaceId f) const {
    HalfEdge h = mesh_.half_edge(f);
    const HalfEdge n = mesh_.next(h), p = mesh_.prev(h);
    if (mesh_.origin(n) < mesh_.origin(h)) h = n;
    if (mesh_.origin(p) < mesh_.origin(h)) h = p;
    return h;
  }

  std::array<VertexId, 3> corners(FaceId f) const {
    const HalfEdge h = first_edge(f);
    return {mesh_.origin(h), mesh_.dest(h), mesh_.apex(h)};
  }

  bool still_there(const Target& t) const {
    return mesh_.is_live(t.face) && corners(t.face) == t.corners;
  }

  // The input's targets, most oversized first and then by vertex ids, so that the queue
  // starts in an order of the surface's own and not of the face slots.
  void queue_first_targets() {
    std::vector<Target> first;
    for (FaceId f = 0; f < mesh_.face_capacity(); ++f)
      if (mesh_.is_live(f)) consider(f, [&](const Target& t) { first.push_back(t); });
    std::sort(first.begin(), first.end(), [](const Target& a, const Target& b) {
      return std::tie(b.excess, a.corners) < std::tie(a.excess, b.corners);
    });
    for (const Target& t : first) targets_.push(t);
  }

  // Hands f to `queue` when it breaks a bound, with how far (size_bounds.hpp).
  template <class Queue>
  void consider(FaceId f, Queue queue) {
    const std::array<VertexId, 3> c = corners(f);
    const double excess = bounds_.excess(points_[c[0]], points_[c[1]], points_[c[2]]);
    if (excess > 0.0) queue(Target{excess, f, c});
  }

  // Longest in 3D; between equal lengths, the smaller pair of vertex ids (lepp.hpp's rule),
  // so both sides of an edge agree on it whatever the data structure.
  HalfEdge longest_edge(FaceId f) const {
    HalfEdge best = kNone;
    double best_length = -1.0;
    std::uint64_t best_key = 0;
    const HalfEdge first = mesh_.half_edge(f);
    for (const HalfEdge h : {first, mesh_.next(first), mesh_.prev(first)}) {
      const VertexId a = mesh_.origin(h), b = mesh_.dest(h);
      const double l = squared_length(points_[a], points_[b]);
      const std::uint64_t k = edge_tie_key(a, b);
      if (l > best_length || (l == best_length && k < best_key)) {
        best = h;
        best_length = l;
        best_key = k;
      }
    }
    return best;
  }

  // The half-edge on the other side of h's edge: the mesh's twin, or across a seam; kNone
  // on the surface's border.
  HalfEdge across(HalfEdge h) const {
    const HalfEdge t = mesh_.twin(h);
    return t != kNone ? t : seams_.across(mesh_.origin(h), mesh_.dest(h));
  }

  // Lepp(f) up to its terminal edge, as a half-edge of the last triangle of the path. The
  // order (length, then ids) is strict, so every step goes to a longer edge and the walk
  // ends.
  HalfEdge terminal_edge(FaceId f) const {
    HalfEdge e = longest_edge(f);
    for (;;) {
      const HalfEdge t = across(e);
      if (t == kNone) return e;
      const HalfEdge next = longest_edge(mesh_.face(t));
      if (next == t) return e;
      e = next;
    }
  }

  // The step's opening: the target and every bound it breaks, measured in 3D.
  void record_target(const Target& t) {
    rec_.step_begin(mesh_, replay::StepKind::bisect);
    const auto& c = t.corners;
    const Point3 &a = points_[c[0]], &b = points_[c[1]], &p = points_[c[2]];
    const double longest = std::max({squared_length(a, b), squared_length(b, p), squared_length(p, a)});
    if (options_.max_edge > 0.0 && longest > max_edge_squared_)
      rec_.criterion_test(replay::Criterion::size, false, c[0], c[1], c[2], std::sqrt(longest));
    if (options_.max_area > 0.0 && area(a, b, p) > options_.max_area)
      rec_.criterion_test(replay::Criterion::max_area, false, c[0], c[1], c[2], area(a, b, p));
  }

  // The Lepp path from f to the terminal edge e, for the log.
  void record_lepp_path(FaceId f, HalfEdge e, std::uint32_t terminal_triangles) {
    path_vertices_.clear();
    for (HalfEdge h = longest_edge(f);;) {
      const std::array<VertexId, 3> k = corners(mesh_.face(h));
      path_vertices_.insert(path_vertices_.end(), k.begin(), k.end());
      if (h == e) break;
      h = longest_edge(mesh_.face(across(h)));
    }
    rec_.lepp_path(mesh_.origin(e), mesh_.dest(e), terminal_triangles, path_vertices_);
  }

  // One bisection on f's path. False when none is possible: the cap is reached, or the
  // doubles cannot cut the edge (then f stays as it is, counted in too_fine_to_cut).
  bool bisect_terminal_edge(FaceId f) {
    const HalfEdge e = terminal_edge(f);
    const HalfEdge t = across(e);
    const VertexId a = mesh_.origin(e), b = mesh_.dest(e);
    const Point3 m = midpoint(points_[a], points_[b]);
    if (!cuttable(e, m) || (t != kNone && !cuttable(t, m))) {
      ++too_fine_to_cut_;
      return false;
    }
    const std::size_t triangles_after = mesh_.face_count() + (t == kNone ? 1 : 2);
    if ((options_.max_triangles > 0 && triangles_after > options_.max_triangles) ||
        triangles_after > kMostFaces || points_.size() >= kInfiniteVertex) {
      capped_ = true;
      return false;
    }
    const VertexId v = static_cast<VertexId>(points_.size());
    grow_huge(points_);
    points_.push_back(m);
    mesh_.set_vertex_count(points_.size());
    if constexpr (Rec::enabled) {
      record_lepp_path(f, e, t == kNone ? 1 : 2);
      rec_.vertex(v, Point{m.x, m.y});
      rec_.elevation(v, m.z);
    }
    const auto split = [&](HalfEdge h) { return rec_.split_edge(mesh_, h, v, replay::SplitReason::bisection); };
    std::size_t count = 0;
    if (t == kNone || mesh_.twin(e) == t) {
      count = faces_of_split(split(e), new_faces_.data());
    } else {
      // A seam: both sides are borders of the mesh, each cut on its own, and the two
      // halves become seams in turn.
      seams_.remove(a, b);
      seams_.add(a, v);
      seams_.add(v, b);
      count = faces_of_split(split(e), new_faces_.data());
      count += faces_of_split(split(t), new_faces_.data() + count);
    }
    for (std::size_t i = 0; i < count; ++i) {
      note_seam_sides(new_faces_[i]);
      consider(new_faces_[i], [this](const Target& t) { targets_.push(t); });
    }
    ++bisections_;
    return true;
  }

  // Whether cutting h's edge at m leaves two true triangles on h's side. The rounded
  // midpoint may fall on an end of a short edge, or, where coordinates of very different
  // magnitudes meet (1 beside 4e27), exactly on the line from an end to the apex: then
  // cutting would make a degenerate triangle, which the exact test refuses.
  bool cuttable(HalfEdge h, const Point3& m) const {
    const Point3 &a = points_[mesh_.origin(h)], &b = points_[mesh_.dest(h)], &c = points_[mesh_.apex(h)];
    return !collinear(a, m, c) && !collinear(m, b, c);
  }

  // The faces round the new vertex after split_edge returned r = v->b in (v, b, c): that
  // face, (a, v, c) beside it, and, when the edge had a twin, (b, v, d) and (v, a, d).
  std::size_t faces_of_split(HalfEdge r, FaceId* out) const {
    out[0] = mesh_.face(r);
    out[1] = mesh_.face(mesh_.twin(mesh_.prev(r)));
    const HalfEdge back = mesh_.twin(r);
    if (back == kNone) return 2;
    out[2] = mesh_.face(back);
    out[3] = mesh_.face(mesh_.twin(mesh_.next(back)));
    return 4;
  }

  void note_seam_sides(FaceId f) {
    if (seams_.empty()) return;
    const HalfEdge first = mesh_.half_edge(f);
    for (const HalfEdge h : {first, mesh_.next(first), mesh_.prev(first)})
      if (mesh_.twin(h) == kNone) seams_.set_if_seam(mesh_.origin(h), mesh_.dest(h), h);
  }

  Mesh& mesh_;
  SeamTable& seams_;
  std::vector<Point3>& points_;
  const BisectionOptions& options_;
  Rec& rec_;
  double max_edge_squared_;
  SizeBounds bounds_;  // the flips after the bisection keep to the same measure
  std::vector<VertexId> path_vertices_;  // recording: the Lepp path's triangles
  TargetQueue targets_;
  std::array<FaceId, 4> new_faces_{};
  std::size_t bisections_ = 0;
  std::size_t too_fine_to_cut_ = 0;
  bool capped_ = false;
};

}  // namespace meshstep::surface::detail
