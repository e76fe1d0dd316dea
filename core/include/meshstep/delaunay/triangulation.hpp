// Incremental Delaunay triangulation over any TriangleMesh.
//
// The triangulation is closed into a sphere by a vertex at infinity: the faces incident
// to it ("ghost" faces) stand for the outside of each convex-hull edge. A ghost face
// (u, v, inf) is in conflict with a point strictly outside its hull edge uv, or on the open
// segment uv. Every other in-circle decision goes through incircle_perturbed, so the
// result is the unique Delaunay triangulation of the perturbed lifting: flips and
// cavities, on every data structure, reach the same triangles.
#pragma once

#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/geometry/predicates.hpp"
#include "meshstep/huge_array.hpp"
#include "meshstep/huge_pages.hpp"
#include "meshstep/mesh/concept.hpp"
#include "meshstep/replay/recorder.hpp"

namespace meshstep {

struct Location {
  enum class Kind : std::uint8_t { in_face, on_edge, on_vertex };
  Kind kind;
  // in_face: a half-edge of the face; on_edge: the edge; on_vertex: a half-edge leaving it.
  HalfEdge half_edge;
};

// Rec is the recording policy (replay/recorder.hpp): every mesh mutation goes through it,
// and it is told of each step, vertex and point location. replay::NullRecorder compiles to
// nothing.
template <TriangleMesh Mesh, class Rec = replay::NullRecorder>
class Triangulation {
 public:
  Triangulation(std::vector<Point> points, Insertion insertion, Rec recorder = {})
      : points_(std::move(points)), insertion_(insertion), rec_(std::move(recorder)) {
    mesh_.reserve(points_.size(), 2 * points_.size() + 8);
    mesh_.set_vertex_count(points_.size());
  }

  const Mesh& mesh() const { return mesh_; }
  Mesh& mesh() { return mesh_; }
  const std::vector<Point>& points() const { return points_; }
  const Point& point(VertexId v) const { return points_[v]; }
  Insertion insertion() const { return insertion_; }
  Rec& recorder() { return rec_; }

  // Mutations for the algorithms built on the triangulation, recorded like its own.
  HalfEdge flip(HalfEdge h, replay::FlipReason reason) { return rec_.flip(mesh_, h, reason); }
  void set_constrained(HalfEdge h, bool on, int marker) { rec_.set_constrained(mesh_, h, on, marker); }
  void remove_face(FaceId f, replay::RemoveReason reason) { rec_.remove_face(mesh_, f, reason); }
  // Removes origin(h), of degree 3 (see TriangleMesh::merge_star); its id stays taken.
  HalfEdge merge_star(HalfEdge h) {
    removed_.push_back(mesh_.origin(h));
    return rec_.merge_star(mesh_, h);
  }
  // The vertices merge_star removed, in the order it removed them.
  const std::vector<VertexId>& removed_vertices() const { return removed_; }

  // Inserts every point in index order (callers sort the points spatially first); the first
  // three non-collinear ones start the triangulation. A point equal to an earlier one is
  // not inserted: merged_into(v) names the vertex that stands for it. Throws InputError
  // when fewer than three points are not collinear.
  void insert_all() {
    merged_into_.assign(points_.size(), kNone);
    start();
    HalfEdge hint = mesh_.vertex_half_edge(first_[0]);
    for (VertexId v = 0; v < points_.size(); ++v) {
      if (v == first_[0] || v == first_[1] || v == first_[2]) continue;
      hint = insert(v, hint);
    }
  }

  // Inserts vertex v (already in points()) by the configured strategy, starting the walk at
  // `hint`. Returns a half-edge leaving the vertex that now stands at v's position (v
  // itself, or the vertex v duplicates, recorded by merged_into()).
  HalfEdge insert(VertexId v, HalfEdge hint) {
    rec_.step_begin(mesh_, replay::StepKind::insert_vertex, v);
    return insert_in_step(v, hint);
  }

  // The same within a step the caller opened (a refinement step, say).
  HalfEdge insert_in_step(VertexId v, HalfEdge hint) {
    const Location loc = locate(points_[v], hint);
    if constexpr (Rec::enabled)
      rec_.locate(v, walk_, mesh_.face(loc.half_edge), static_cast<replay::LocateResult>(loc.kind));
    if (loc.kind == Location::Kind::on_vertex) {
      merged_into_[v] = mesh_.origin(loc.half_edge);
      ++duplicates_;
      rec_.duplicate(v, merged_into_[v], points_[v]);
      return loc.half_edge;
    }
    rec_.vertex(v, points_[v]);
    return insertion_ == Insertion::flip ? insert_by_flips(v, loc) : insert_by_cavity(v, loc);
  }

  // Adds a new point and splits the edge of h with it, whatever the exact position of the
  // point (used for rounded intersection points that belong on a constrained edge), then
  // restores the Delaunay property around it. Returns a half-edge leaving the new vertex.
  HalfEdge insert_on_edge(const Point& p, HalfEdge h,
                          replay::SplitReason reason = replay::SplitReason::crossing) {
    const VertexId v = add_point(p);
    rec_.vertex(v, p);
    legalize_around(rec_.split_edge(mesh_, h, v, reason));
    return mesh_.vertex_half_edge(v);  // the split's own handle may have been flipped away
  }

  // Splits the edge of h (and the faces on both sides) at p, a point on it, and leaves the
  // mesh as it is: longest-edge bisection, not Delaunay. Returns a half-edge leaving the
  // new vertex.
  HalfEdge bisect(const Point& p, HalfEdge h) {
    const VertexId v = add_point(p);
    rec_.vertex(v, p);
    rec_.split_edge(mesh_, h, v, replay::SplitReason::bisection);
    return mesh_.vertex_half_edge(v);
  }

  VertexId add_point(const Point& p) {
    grow_huge(points_);
    points_.push_back(p);
    merged_into_.push_back(kNone);
    mesh_.set_vertex_count(points_.size());
    return static_cast<VertexId>(points_.size() - 1);
  }

  VertexId merged_into(VertexId v) const { return merged_into_[v]; }
  std::size_t duplicate_count() const { return duplicates_; }

  bool is_ghost(FaceId f) const {
    const HalfEdge h = mesh_.half_edge(f);
    return mesh_.origin(h) == kInfiniteVertex || mesh_.dest(h) == kInfiniteVertex ||
           mesh_.apex(h) == kInfiniteVertex;
  }

  // Would a point at p be in conflict with face f (inside its circumcircle, or beyond its
  // hull edge for a ghost face)? Cocircular ties are broken by the perturbation.
  bool in_conflict(FaceId f, const Point& p) const {
    const HalfEdge h = mesh_.half_edge(f);
    return in_conflict(mesh_.origin(h), mesh_.dest(h), mesh_.apex(h), p);
  }

  // Is the edge of h locally Delaunay (or constrained, or on the boundary)?
  bool is_locally_delaunay(HalfEdge h) const {
    const HalfEdge t = mesh_.twin(h);
    if (t == kNone || mesh_.is_constrained(h)) return true;
    const VertexId d = mesh_.apex(t);
    if (d == kInfiniteVertex) return true;
    return !in_conflict(mesh_.origin(h), mesh_.dest(h), mesh_.apex(h), points_[d]);
  }

  // Flips every edge in `stack` that is not locally Delaunay, pushing the four outer edges
  // of each flipped quadrilateral, until the stack is empty. Entries may name edges that
  // later flips moved: checking any live edge is harmless, and an edge whose face a flip
  // changed is on that flip's quadrilateral, so it is pushed again.
  // `flipped`, if given, receives the two faces of every flip (some appear more than once,
  // and a later flip may have changed what they hold).
  void make_delaunay(std::vector<HalfEdge>& stack, std::vector<FaceId>* flipped = nullptr) {
    while (!stack.empty()) {
      const HalfEdge h = stack.back();
      stack.pop_back();
      if (!mesh_.is_live(mesh_.face(h)) || is_locally_delaunay(h)) continue;
      const HalfEdge d = flip(h, replay::FlipReason::delaunay);  // apex(h) -> apex(twin(h))
      const HalfEdge e = mesh_.twin(d);
      if (flipped) flipped->insert(flipped->end(), {mesh_.face(d), mesh_.face(e)});
      stack.push_back(mesh_.next(d));
      stack.push_back(mesh_.prev(d));
      stack.push_back(mesh_.next(e));
      stack.push_back(mesh_.prev(e));
    }
  }

  // Walk from the face of `start` towards p. Visibility walk; the first edge tested in each
  // face is picked by a seeded generator so that the walk terminates in constrained
  // (non-Delaunay) triangulations as well, while results stay reproducible.
  // Flattened, like the other per-insertion loops: GCC would otherwise keep the
  // predicates and vector growth out of line here, at a cost of about a third.
  [[gnu::flatten]] Location locate(const Point& p, HalfEdge start) const {
    HalfEdge h = start;
    bool entered = false;  // true when we came in through h, so p is strictly left of h
    if constexpr (Rec::enabled) walk_.start();
    for (;;) {
      VertexId a = mesh_.origin(h), b = mesh_.dest(h);
      const VertexId c = mesh_.apex(h);
      if constexpr (Rec::enabled) walk_.enter(mesh_.corner(h), a, b, c);
      if (a == kInfiniteVertex || b == kInfiniteVertex || c == kInfiniteVertex) {
        if (a == kInfiniteVertex) h = mesh_.next(h);
        if (b == kInfiniteVertex) h = mesh_.prev(h);
        a = mesh_.origin(h);
        b = mesh_.dest(h);
        const double o = orient2d(points_[a], points_[b], p);
        if (o > 0.0) return {Location::Kind::in_face, h};
        if (o < 0.0) {
          h = mesh_.twin(h);
          entered = true;
          continue;
        }
        // On the line of the hull edge a->b.
        if (p == points_[a]) return {Location::Kind::on_vertex, h};
        if (p == points_[b]) return {Location::Kind::on_vertex, mesh_.next(h)};
        if (strictly_between(points_[a], points_[b], p)) return {Location::Kind::on_edge, h};
        // Beyond b or beyond a: move to the ghost face on that side.
        h = strictly_between(points_[a], p, points_[b]) ? mesh_.twin(mesh_.next(h))
                                                        : mesh_.twin(mesh_.prev(h));
        entered = false;
        continue;
      }
      // A real face a, b, c: h = a->b, hn = b->c, hp = c->a.
      const HalfEdge hn = mesh_.next(h), hp = mesh_.prev(h);
      const Point &pa = points_[a], &pb = points_[b], &pc = points_[c];
      if (!entered && orient2d(pa, pb, p) < 0.0) {
        h = mesh_.twin(h);
        entered = true;
        continue;
      }
      const bool swap = next_random() & 1u;
      const HalfEdge first = swap ? hp : hn, second = swap ? hn : hp;
      const double o_bc = orient2d(pb, pc, p);
      const double o_ca = orient2d(pc, pa, p);
      const double o1 = swap ? o_ca : o_bc, o2 = swap ? o_bc : o_ca;
      if (o1 < 0.0) {
        h = mesh_.twin(first);
        entered = true;
        continue;
      }
      if (o2 < 0.0) {
        h = mesh_.twin(second);
        entered = true;
        continue;
      }
      // p is in the closed face: on a vertex or an edge only if some orientation is zero.
      const double o0 = entered ? 1.0 : orient2d(points_[a], points_[b], p);
      if (o0 != 0.0 && o1 != 0.0 && o2 != 0.0) return {Location::Kind::in_face, h};
      for (const HalfEdge e : {h, hn, hp})
        if (p == points_[mesh_.origin(e)]) return {Location::Kind::on_vertex, e};
      if (o0 == 0.0) return {Location::Kind::on_edge, h};
      if (o1 == 0.0) return {Location::Kind::on_edge, first};
      if (o2 == 0.0) return {Location::Kind::on_edge, second};
      return {Location::Kind::in_face, h};
    }
  }

  // Some half-edge from a to b, or kNone. Looked for among the faces round a and, as an
  // edge coming into b, among the faces round b: a vertex where the domain pinches (two
  // boundary fans meeting at one point) keeps only one fan in vertex_half_edge, and which one
  // depends on the data structure, so one end alone may miss the edge.
  HalfEdge find_edge(VertexId a, VertexId b) const {
    const HalfEdge from_a = first_out_edge(mesh_.vertex_half_edge(a), [&](HalfEdge h) { return mesh_.dest(h) == b; });
    if (from_a != kNone) return from_a;
    const HalfEdge into_b =
        first_out_edge(mesh_.vertex_half_edge(b), [&](HalfEdge h) { return mesh_.origin(mesh_.prev(h)) == a; });
    return into_b == kNone ? kNone : mesh_.prev(into_b);
  }

  // The first half-edge leaving origin(out) that `pred` accepts, going counterclockwise from
  // out, then on a boundary clockwise; kNone if none does (or out is kNone).
  template <class Pred>
  HalfEdge first_out_edge(HalfEdge out, Pred&& pred) const {
    if (out == kNone) return kNone;
    HalfEdge h = out;
    do {
      if (pred(h)) return h;
      h = mesh_.twin(mesh_.prev(h));
    } while (h != kNone && h != out);
    if (h == out) return kNone;
    for (HalfEdge t = mesh_.twin(out); t != kNone; t = mesh_.twin(h)) {
      h = mesh_.next(t);
      if (pred(h)) return h;
    }
    return kNone;
  }

  // Calls f for every half-edge leaving origin(out), going counterclockwise; on a boundary
  // also clockwise from out.
  template <class F>
  void for_each_out_edge(HalfEdge out, F&& f) const {
    HalfEdge h = out;
    do {
      f(h);
      const HalfEdge t = mesh_.twin(mesh_.prev(h));
      if (t == kNone) {
        // Open fan: go the other way from `out`.
        HalfEdge g = out;
        for (;;) {
          const HalfEdge u = mesh_.twin(g);
          if (u == kNone) return;
          g = mesh_.next(u);
          f(g);
        }
      }
      h = t;
    } while (h != out);
  }

 private:
  // Ghost-aware conflict test of point p against the counterclockwise face (a, b, c).
  bool in_conflict(VertexId a, VertexId b, VertexId c, const Point& p) const {
    if (c == kInfiniteVertex) return hull_edge_conflict(a, b, p);
    if (a == kInfiniteVertex) return hull_edge_conflict(b, c, p);
    if (b == kInfiniteVertex) return hull_edge_conflict(c, a, p);
    return incircle_perturbed(points_[a], points_[b], points_[c], p) > 0;
  }

  // Ghost face (u, v, inf): conflict when p is strictly outside u->v or on the open segment.
  bool hull_edge_conflict(VertexId u, VertexId v, const Point& p) const {
    const double o = orient2d(points_[u], points_[v], p);
    return o > 0.0 || (o == 0.0 && strictly_between(points_[u], points_[v], p));
  }

  void start() {
    const std::size_t n = points_.size();
    if (n == 0) throw InputError("no vertices to triangulate");
    const VertexId a = 0;
    VertexId b = 1;
    while (b < n && points_[b] == points_[a]) ++b;
    if (b == n)
      throw InputError("all " + std::to_string(n) +
                       " vertices are at the same place: nothing to triangulate");
    VertexId c = b + 1;
    double o = 0.0;
    while (c < n && (o = orient2d(points_[a], points_[b], points_[c])) == 0.0) ++c;
    if (c == n)
      throw InputError("all " + std::to_string(n) +
                       " vertices lie on one line: a triangulation needs three that do not");
    first_ = {a, b, c};
    rec_.step_begin(mesh_, replay::StepKind::start);
    for (const VertexId v : first_) rec_.vertex(v, points_[v]);
    if (o > 0.0)
      rec_.init_sphere(mesh_, a, b, c);
    else
      rec_.init_sphere(mesh_, a, c, b);
  }

  [[gnu::flatten]] HalfEdge insert_by_flips(VertexId v, const Location& loc) {
    const HalfEdge out = loc.kind == Location::Kind::in_face
                             ? rec_.split_face(mesh_, mesh_.face(loc.half_edge), v)
                             : rec_.split_edge(mesh_, loc.half_edge, v, replay::SplitReason::insert);
    legalize_around(out);
    return mesh_.vertex_half_edge(v);
  }

  // Lawson: the edges opposite v are the only suspects; a flip makes two new ones.
  [[gnu::flatten]] void legalize_around(HalfEdge out) {
    stack_.clear();
    for_each_out_edge(out, [&](HalfEdge h) { stack_.push_back(mesh_.next(h)); });
    while (!stack_.empty()) {
      const HalfEdge h = stack_.back();
      stack_.pop_back();
      if (is_locally_delaunay(h)) continue;
      const HalfEdge e = flip(h, replay::FlipReason::delaunay);  // v -> the far vertex
      stack_.push_back(mesh_.next(e));
      stack_.push_back(mesh_.prev(mesh_.twin(e)));
    }
  }

  [[gnu::flatten]] HalfEdge insert_by_cavity(VertexId v, const Location& loc) {
    const Point& p = points_[v];
    cavity_.clear();
    cavity_.push_back(mesh_.face(loc.half_edge));
    const bool on_edge = loc.kind == Location::Kind::on_edge;
    const bool split_constraint = on_edge && mesh_.is_constrained(loc.half_edge);
    VertexId split_a = kNone, split_b = kNone;
    if (on_edge) {
      split_a = mesh_.origin(loc.half_edge);
      split_b = mesh_.dest(loc.half_edge);
      const HalfEdge t = mesh_.twin(loc.half_edge);
      if (t != kNone) cavity_.push_back(mesh_.face(t));
    }
    // Grow across unconstrained edges into faces whose circle contains p. The edge p lies
    // on is crossed even when constrained: p splits it.
    for (std::size_t i = 0; i < cavity_.size(); ++i) {
      const HalfEdge first = mesh_.half_edge(cavity_[i]);
      for (HalfEdge h : {first, mesh_.next(first), mesh_.prev(first)}) {
        const HalfEdge t = mesh_.twin(h);
        if (t == kNone || mesh_.is_constrained(h)) continue;
        const FaceId g = mesh_.face(t);
        if (in_cavity(g) || !in_conflict(g, p)) continue;
        cavity_.push_back(g);
      }
    }
    // Boundary: edges of cavity faces whose other side is not in the cavity.
    boundary_.clear();
    for (const FaceId f : cavity_) {
      const HalfEdge first = mesh_.half_edge(f);
      for (HalfEdge h : {first, mesh_.next(first), mesh_.prev(first)}) {
        const HalfEdge t = mesh_.twin(h);
        if (t == kNone || !in_cavity(mesh_.face(t))) boundary_.push_back(h);
      }
    }
    // Chain the boundary counterclockwise: each edge starts where the previous one ends.
    for (std::size_t i = 0; i + 1 < boundary_.size(); ++i) {
      const VertexId end = mesh_.dest(boundary_[i]);
      for (std::size_t j = i + 1; j < boundary_.size(); ++j)
        if (mesh_.origin(boundary_[j]) == end) {
          std::swap(boundary_[i + 1], boundary_[j]);
          break;
        }
    }
    const HalfEdge out = rec_.star_cavity(mesh_, boundary_, cavity_, v);
    if (split_constraint) {
      for_each_out_edge(out, [&](HalfEdge h) {
        const VertexId w = mesh_.dest(h);
        if (w == split_a || w == split_b) set_constrained(h, true, 0);
      });
    }
    return out;
  }

  bool in_cavity(FaceId f) const {
    for (const FaceId g : cavity_)
      if (g == f) return true;
    return false;
  }

  std::uint32_t next_random() const {
    // xorshift32: cheap, and seeded identically for every run.
    random_ ^= random_ << 13;
    random_ ^= random_ >> 17;
    random_ ^= random_ << 5;
    return random_;
  }

  std::vector<Point> points_;
  Insertion insertion_;
  Mesh mesh_;
  std::vector<VertexId> removed_;
  HugeArray<VertexId> merged_into_;
  std::size_t duplicates_ = 0;
  std::array<VertexId, 3> first_{kNone, kNone, kNone};
  mutable std::uint32_t random_ = 0x9E3779B9u;
  [[no_unique_address]] Rec rec_;
  // The faces the last walk went through, for the locate event: nothing unless recording.
  [[no_unique_address]] mutable std::conditional_t<Rec::enabled, replay::WalkTrace, replay::NoWalkTrace> walk_;
  // Scratch, kept across insertions so that inserting allocates nothing in steady state.
  std::vector<HalfEdge> stack_;
  std::vector<FaceId> cavity_;
  std::vector<HalfEdge> boundary_;
};

}  // namespace meshstep
