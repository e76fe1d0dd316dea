// Constrained Delaunay: inserting segments into a Delaunay triangulation.
//
// A segment a-b is recovered by flips (Sloan 1993): the edges it crosses are collected by
// walking along it, then each one whose quadrilateral is convex is flipped, until none
// crosses; the new edges are then made Delaunay again, constrained edges excepted. On the
// way the walk can meet
//  - a vertex lying on a-b: the segment is split there (a T-junction);
//  - a constrained edge crossing a-b: both are split at their intersection point, which is
//    rounded to doubles and becomes a Steiner vertex.
// Two input segments cross at one point at most, so a run makes about one crossing vertex
// per pair of input segments: a bound on that is what makes it end. Rounding can break
// it: when a segment ends exactly on another whose piece there runs between two rounded
// crossings, the piece passes an ulp beside the end, and their "crossing" rounded to an
// ulp beside it again; its pieces then cross the same pair's once more, an ulp further,
// without end (fuzz_polygons, issue 31). So a crossing within rounding of an endpoint of
// either segment goes through that endpoint, and a pair of input segments whose pieces
// cross more than a few times is refused.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <deque>
#include <optional>
#include <string>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/error.hpp"
#include "meshstep/geometry/magnitudes.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep {

template <TriangleMesh Mesh, class Rec = replay::NullRecorder>
class SegmentInserter {
 public:
  explicit SegmentInserter(Triangulation<Mesh, Rec>& tri) : tri_(tri) {}

  // One step: the segment a-b with every piece it is split into.
  // `index` names the segment among the input's (for messages and to count the crossings
  // of each pair); distinct segments need distinct indices.
  void insert(VertexId a, VertexId b, int marker, std::uint32_t index) {
    tri_.recorder().step_begin(tri_.mesh(), replay::StepKind::recover_segment, a, b);
    if (source_ends_.empty()) input_vertices_ = tri_.points().size();  // segments come after every vertex
    if (index >= source_ends_.size()) source_ends_.resize(index + 1, {kInfiniteVertex, kInfiniteVertex});
    source_ends_[index] = {a, b};
    pending_.push_back({a, b, marker, index});
    while (!pending_.empty()) {
      const Piece piece = pending_.back();
      pending_.pop_back();
      insert_piece(piece);
    }
  }

  // What a constrained edge carries: its marker, and the input segment it is a piece of
  // (kNoSource for none), to count the crossings of each pair of input segments.
  static constexpr std::uint32_t kNoSource = static_cast<std::uint32_t>(-1);
  struct Constraint {
    int marker;
    std::uint32_t source;
  };
  // Every constrained edge, keyed by its endpoints (smaller id first).
  const std::unordered_map<std::uint64_t, Constraint>& constraints() const { return constraints_; }
  static std::uint64_t edge_key(VertexId a, VertexId b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
  }
  std::size_t steiner_count() const { return steiner_; }
  std::size_t split_count() const { return splits_; }

 private:
  struct Pair {
    VertexId first, second;
  };
  struct Piece {
    VertexId a, b;
    int marker;
    std::uint32_t source;  // the input segment it is a piece of
  };
  const Point& P(VertexId v) const { return tri_.point(v); }
  const Mesh& mesh() const { return tri_.mesh(); }

  void constrain(HalfEdge h, int marker, std::uint32_t source) {
    tri_.set_constrained(h, true, marker);
    constraints_[edge_key(mesh().origin(h), mesh().dest(h))] = {marker, source};
  }
  // What r-l carries; an edge not recorded here takes `marker` and no source.
  Constraint constraint_of(VertexId r, VertexId l, int marker) const {
    const auto it = constraints_.find(edge_key(r, l));
    return it == constraints_.end() ? Constraint{marker, kNoSource} : it->second;
  }

  // The two ends of the input segment the piece is part of (nullptr: none recorded).
  const Pair* source_ends(const Piece& piece) const {
    if (piece.source >= source_ends_.size() || source_ends_[piece.source].first == kInfiniteVertex) return nullptr;
    return &source_ends_[piece.source];
  }
  // A piece with a rounded crossing for an end is bent off its input segment's line by an
  // ulp or so, and may pass beside an input vertex that lies exactly on that segment: the
  // vertex is left on one side, and when the piece is a boundary, a later split of it (rounded
  // too) can leave the vertex inside a triangle (issue 31, fuzz_refine_options: the segment
  // (1,3)-(4,0) through the input vertex (3,1), split first where another crosses it).
  // Such a vertex is on the segment's chain: the piece is split there. Every vertex an ulp
  // beside the piece borders the faces it crosses (an end of a crossed edge) or, when the
  // piece is an edge already, is the apex of a face of it.
  bool bent(const Piece& piece) const {
    const Pair* ends = source_ends(piece);
    if (!ends || (ends->first == piece.a && ends->second == piece.b)) return false;  // none, or the whole segment
    const Point &s = P(ends->first), &t = P(ends->second);
    return orient2d(s, t, P(piece.a)) != 0.0 || orient2d(s, t, P(piece.b)) != 0.0;
  }
  // An input vertex exactly on the piece's input segment, strictly inside it, and ahead of a
  // towards b (no vertex within rounding of a or b: those are snapped to them).
  bool on_source_segment(const Piece& piece, VertexId y) const {
    const Pair* ends = source_ends(piece);
    if (!ends || y == kInfiniteVertex || y >= input_vertices_ || y == piece.a || y == piece.b) return false;
    const Point &s = P(ends->first), &t = P(ends->second);
    const Point &a = P(piece.a), &b = P(piece.b), &v = P(y);
    return orient2d(s, t, v) == 0.0 && strictly_between(s, t, v) &&
           (v.x - a.x) * (b.x - a.x) + (v.y - a.y) * (b.y - a.y) > 0.0 &&
           (v.x - b.x) * (a.x - b.x) + (v.y - b.y) * (a.y - b.y) > 0.0;
  }

  // Inserts the piece a-b, or pushes the pieces it must be split into onto pending_.
  void insert_piece(const Piece& piece) {
    const VertexId a = piece.a, b = piece.b;
    if (a == b) return;
    const bool is_bent = bent(piece);
    if (const HalfEdge h = tri_.find_edge(a, b); h != kNone) {
      if (is_bent)
        for (const HalfEdge side : {h, mesh().twin(h)})
          if (const VertexId y = mesh().apex(side); on_source_segment(piece, y)) {
            split_at_vertex(piece, y);
            return;
          }
      constrain(h, piece.marker, piece.source);
      return;
    }
    // Find the face around a whose wedge holds the direction to b.
    const HalfEdge start = mesh().vertex_half_edge(a);
    HalfEdge h = start, entry = kNone;
    do {
      const VertexId u = mesh().dest(h), w = mesh().apex(h);
      if (u != kInfiniteVertex && orient2d(P(a), P(u), P(b)) == 0.0 &&
          strictly_between(P(a), P(b), P(u))) {
        split_at_vertex(piece, u);  // u lies on the segment
        return;
      }
      if (u != kInfiniteVertex && w != kInfiniteVertex && orient2d(P(a), P(u), P(b)) > 0.0 &&
          orient2d(P(a), P(w), P(b)) < 0.0) {
        entry = mesh().next(h);  // u -> w, crossed by the segment
        break;
      }
      h = mesh().twin(mesh().prev(h));
    } while (h != start);
    if (entry == kNone) throw std::logic_error("segment insertion: no face around the start vertex");

    // Walk along a-b collecting crossed edges (each from its right to its left endpoint).
    crossed_.clear();
    HalfEdge e = entry;
    for (;;) {
      if (mesh().is_constrained(e)) {
        split_crossing(piece, e);
        return;
      }
      crossed_.push_back({mesh().origin(e), mesh().dest(e)});
      const HalfEdge t = mesh().twin(e);
      const VertexId y = mesh().apex(t);
      if (y == b) break;
      const double oy = orient2d(P(a), P(b), P(y));
      if (oy == 0.0) {
        split_at_vertex(piece, y);
        return;
      }
      e = oy > 0.0 ? mesh().next(t) : mesh().prev(t);
    }
    if (is_bent)
      for (const Pair& crossed : crossed_)
        for (const VertexId y : {crossed.first, crossed.second})
          if (on_source_segment(piece, y)) {
            split_at_vertex(piece, y);
            return;
          }
    remove_crossings(a, b);
    const HalfEdge ab = tri_.find_edge(a, b);
    if (ab == kNone) throw std::logic_error("segment insertion: segment not recovered");
    constrain(ab, piece.marker, piece.source);
    restore_delaunay();
  }

  void split_at_vertex(const Piece& piece, VertexId mid) {
    ++splits_;
    pending_.push_back({mid, piece.b, piece.marker, piece.source});
    pending_.push_back({piece.a, mid, piece.marker, piece.source});
  }

  // a-b crosses the constrained edge e = r->l: split both at their intersection point.
  void split_crossing(const Piece& piece, HalfEdge e) {
    const VertexId a = piece.a, b = piece.b;
    const int marker = piece.marker;
    const VertexId r = mesh().origin(e), l = mesh().dest(e);
    const Point x = intersection(P(a), P(b), P(r), P(l));
    refuse_out_of_range(x);
    const auto [old_marker, old_source] = constraint_of(r, l, marker);
    ++splits_;
    // The rounded point on an endpoint, or within rounding of one (where a segment ends on
    // the other's line): route the pieces through that vertex.
    if (const VertexId z = endpoint_within_rounding(x, {a, b, r, l}); z != kNone) {
      count_crossing(piece.source, old_source);
      if (z == r || z == l) {
        split_at_vertex(piece, z);
      } else {
        release(e);
        pending_.push_back(piece);  // retried once the old constraint is re-routed
        pending_.push_back({z, l, old_marker, old_source});
        pending_.push_back({r, z, old_marker, old_source});
      }
      return;
    }
    count_crossing(piece.source, old_source);
    if (!splits_cleanly(e, x)) {
      // Rounded off r-l far enough that splitting the edge there would fold a triangle
      // (x close to a vertex of the two faces, or a face nearly flat): x goes in as any
      // point does, and both constraints are recovered through it like other pieces. The
      // old edge is released only after, so the insertion runs on a CDT (its flips mend
      // only what the new vertex breaks).
      const VertexId v = insert_anywhere(x, e);
      release(tri_.find_edge(r, l));
      pending_.push_back({v, b, marker, piece.source});
      pending_.push_back({a, v, marker, piece.source});
      pending_.push_back({v, l, old_marker, old_source});
      pending_.push_back({r, v, old_marker, old_source});
      return;
    }
    const VertexId v = split_constrained(e, x, marker);
    pending_.push_back({v, b, marker, piece.source});
    pending_.push_back({a, v, marker, piece.source});
  }

  // Of the vertices `ends`, the nearest to x if it lies within a few ulps of x in each
  // coordinate (ulps of that coordinate's own magnitude: the scale of the rounding that made
  // x, whatever the other points' magnitudes); else kNone. Snapping there moves a
  // constraint by no more than rounding the crossing to doubles already does.
  VertexId endpoint_within_rounding(const Point& x, std::initializer_list<VertexId> ends) const {
    constexpr double kSnapUlps = 2.0;
    const auto within = [](double c, double d) {
      return std::fabs(c - d) <= kSnapUlps * std::numeric_limits<double>::epsilon() * std::max(std::fabs(c), std::fabs(d));
    };
    VertexId best = kNone;
    double best_distance = 0.0;
    for (const VertexId z : ends) {
      if (!within(x.x, P(z).x) || !within(x.y, P(z).y)) continue;
      const double distance = std::max(std::fabs(x.x - P(z).x), std::fabs(x.y - P(z).y));
      if (best == kNone || distance < best_distance) best = z, best_distance = distance;
    }
    return best;
  }

  // Counts a crossing of the pieces of input segments s and t. Two straight segments cross
  // once; their pieces, bent by rounded crossings with others, may cross a few times more
  // near that point (pencils of nearly concurrent segments), but a pair meeting more than
  // kMaxCrossingsPerPair times is rounding feeding on itself, which would not end: the
  // input is refused. This bound on the vertices a pair can make is what ends every run.
  void count_crossing(std::uint32_t s, std::uint32_t t) {
    constexpr int kMaxCrossingsPerPair = 16;
    if (s == kNoSource || t == kNoSource || s == t) return;
    if (++crossings_[edge_key(s, t)] <= kMaxCrossingsPerPair) return;
    throw InputError("input segments " + std::to_string(std::min(s, t) + 1) + " and " +
                     std::to_string(std::max(s, t) + 1) + " (counting from 1) cross more than " +
                     std::to_string(kMaxCrossingsPerPair) +
                     " times: their crossing, rounded to doubles, lies so close to another vertex or segment "
                     "that splitting them there would not end; move that vertex off the other segment, or "
                     "join them at a shared vertex");
  }

  // Unconstrains the edge of e, to be recovered in pieces through a new vertex. The mesh
  // was a CDT with e constrained; without, e alone may fail the in-circle test, so flipping
  // from it makes a CDT again before the pieces are recovered (Sloan's recovery keeps a
  // CDT only when it starts from one).
  void release(HalfEdge e) {
    const VertexId r = mesh().origin(e), l = mesh().dest(e);
    tri_.set_constrained(e, false, 0);
    constraints_.erase(edge_key(r, l));
    stack_.assign(1, e);
    tri_.make_delaunay(stack_);
  }

  // Splits the constrained edge of e at x, a point on it (or near enough that every new
  // triangle is counterclockwise); both halves keep its marker. Returns the new vertex.
  VertexId split_constrained(HalfEdge e, const Point& x, int unknown_marker) {
    const VertexId r = mesh().origin(e), l = mesh().dest(e);
    const auto [marker, source] = constraint_of(r, l, unknown_marker);
    constraints_.erase(edge_key(r, l));
    const HalfEdge out = tri_.insert_on_edge(x, e);
    const VertexId v = mesh().origin(out);
    ++steiner_;
    mend_edges_round(out);
    constraints_[edge_key(r, v)] = {marker, source};
    constraints_[edge_key(v, l)] = {marker, source};
    if constexpr (Rec::enabled) {
      // The halves kept the old edge's flag; record that they carry its marker too.
      tri_.set_constrained(tri_.find_edge(r, v), true, marker);
      tri_.set_constrained(tri_.find_edge(v, l), true, marker);
    }
    return v;
  }

  // insert_on_edge() flips only the edges opposite the new vertex: enough for a point
  // exactly on the edge, where the edges from it are Delaunay by construction. A rounded
  // crossing lies a hair off the edge, and when it is also within a few ulps of one of the
  // edge's ends an edge from it to an apex can fail the in-circle test (issue 31: a crossing
  // 4e-16 from a vertex left such an edge, and `check` refused the mesh). So the edges from
  // the new vertex are checked too, with their quadrilaterals' outer edges as flips go.
  void mend_edges_round(HalfEdge out) {
    stack_.clear();
    tri_.for_each_out_edge(out, [&](HalfEdge h) {
      stack_.push_back(h);
      stack_.push_back(mesh().next(h));
    });
    tri_.make_delaunay(stack_);
  }

  // Would splitting the edge of e (r -> l) at x leave every new triangle counterclockwise?
  // True for a point on the open edge; a rounded one may be off it by an ulp or so, which
  // matters only when a face is nearly flat or x is nearly on one of its other sides.
  bool splits_cleanly(HalfEdge e, const Point& x) const {
    const VertexId r = mesh().origin(e), l = mesh().dest(e);
    for (const HalfEdge side : {e, mesh().twin(e)}) {
      const VertexId from = mesh().origin(side), to = mesh().dest(side), apex = mesh().apex(side);
      if (apex == kInfiniteVertex) {
        if (orient2d(P(r), P(l), x) != 0.0) return false;  // the hull would bend at x
        continue;
      }
      if (!(orient2d(P(from), x, P(apex)) > 0.0 && orient2d(x, P(to), P(apex)) > 0.0)) return false;
    }
    return true;
  }

  // Inserts x by point location and flips (constrained edges kept), or finds the vertex
  // already there. Returns the vertex at x.
  VertexId insert_anywhere(const Point& x, HalfEdge near) {
    const auto at = tri_.locate(x, near);
    if (at.kind == Location::Kind::on_vertex) return mesh().origin(at.half_edge);
    if (at.kind == Location::Kind::on_edge && mesh().is_constrained(at.half_edge))
      return split_constrained(at.half_edge, x, 0);  // exactly on another constraint
    const VertexId v = tri_.add_point(x);
    tri_.insert_in_step(v, at.half_edge);
    ++steiner_;
    return v;
  }

  // The crossing of a-b and r-l, rounded. Measured along the shorter segment from its end
  // nearer the crossing (the parameter's rounding error is multiplied by the distance
  // travelled, which a segment 1e16 long would turn into whole units), then kept within
  // both segments' boxes, where the exact crossing lies. The parameter is the ratio of the
  // shorter segment's ends' distances to the other's line, each from its exact value
  // (orient2d_value): in doubles, the distance of (0, 1) to a line through (0.1, 0.7) and
  // (9e15, 2.9e16) lost every digit, and the crossing fell 0.1 off both segments (issue 31,
  // the hour-long fuzz of refine_options).
  // The range rule (geometry/magnitudes.hpp) holds for crossings too: a crossing far smaller
  // in magnitude than the input's largest coordinate would leave the span where the mesh
  // can be computed, and checked, exactly. The range is taken from the points at the first
  // crossing: the input's, as segments are inserted after every vertex.
  void refuse_out_of_range(const Point& x) {
    if (!range_) range_.emplace(tri_.points());
    if (!range_->holds(x))
      throw InputError("two segments cross at a point with a nonzero coordinate more than 2^" +
                       std::to_string(kSpanExponent) +
                       " (about 1e42) times smaller than the input's largest coordinate; meshstep computes exactly "
                       "only within that span (the range rule, README)");
  }

  static Point intersection(const Point& a, const Point& b, const Point& r, const Point& l) {
    const auto length2 = [](const Point& p, const Point& q) {
      return (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y);
    };
    const bool along_ab = length2(a, b) <= length2(r, l);
    const Point &p = along_ab ? a : r, &q = along_ab ? b : l;
    const Point &u = along_ab ? r : a, &w = along_ab ? l : b;
    // p and q lie on opposite sides of u-w (they cross): no cancellation in the sums.
    const double from_p = orient2d_value(u, w, p), from_q = orient2d_value(u, w, q);
    const double dx = q.x - p.x, dy = q.y - p.y;
    if (from_p == from_q) return {0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};  // both 0: not a crossing; never asked
    const double t = from_p / (from_p - from_q);  // from p, in [0, 1]
    const double s = from_q / (from_q - from_p);  // from q
    Point x = t <= 0.5 ? Point{p.x + t * dx, p.y + t * dy} : Point{q.x - s * dx, q.y - s * dy};
    x.x = std::clamp(x.x, std::max(std::min(a.x, b.x), std::min(r.x, l.x)), std::min(std::max(a.x, b.x), std::max(r.x, l.x)));
    x.y = std::clamp(x.y, std::max(std::min(a.y, b.y), std::min(r.y, l.y)), std::min(std::max(a.y, b.y), std::max(r.y, l.y)));
    return x;
  }

  // Sloan's loop: flip crossing edges whose quadrilateral is convex until none crosses.
  void remove_crossings(VertexId a, VertexId b) {
    queue_.assign(crossed_.begin(), crossed_.end());
    created_.clear();
    std::size_t stalls = 0;
    while (!queue_.empty()) {
      const Pair edge = queue_.front();
      queue_.pop_front();
      const HalfEdge h = tri_.find_edge(edge.first, edge.second);
      const VertexId c1 = mesh().apex(h), c2 = mesh().apex(mesh().twin(h));
      const double o_r = orient2d(P(c1), P(c2), P(edge.first));
      const double o_l = orient2d(P(c1), P(c2), P(edge.second));
      if (!((o_r > 0.0 && o_l < 0.0) || (o_r < 0.0 && o_l > 0.0))) {
        queue_.push_back(edge);  // not convex yet: another flip will make it so
        if (++stalls > 4 * queue_.size() + 16)
          throw std::logic_error("segment insertion: no convex quadrilateral left");
        continue;
      }
      stalls = 0;
      tri_.flip(h, replay::FlipReason::segment_recovery);  // now c1 -> c2
      const bool touches_segment = c1 == a || c1 == b || c2 == a || c2 == b;
      const double s1 = orient2d(P(a), P(b), P(c1)), s2 = orient2d(P(a), P(b), P(c2));
      if (!touches_segment && ((s1 > 0.0 && s2 < 0.0) || (s1 < 0.0 && s2 > 0.0)))
        queue_.push_back(s1 < 0.0 ? Pair{c1, c2} : Pair{c2, c1});
      else
        created_.push_back({c1, c2});
    }
  }

  void restore_delaunay() {
    stack_.clear();
    for (const Pair& e : created_)
      if (const HalfEdge h = tri_.find_edge(e.first, e.second); h != kNone) stack_.push_back(h);
    tri_.make_delaunay(stack_);
  }

  Triangulation<Mesh, Rec>& tri_;
  std::optional<ExactRange> range_;  // made at the first crossing
  std::vector<Pair> source_ends_;     // input segment (its index) -> its two ends
  std::size_t input_vertices_ = 0;   // vertices below this number are the input's
  std::unordered_map<std::uint64_t, Constraint> constraints_;  // one entry per constrained edge
  std::unordered_map<std::uint64_t, int> crossings_;  // pair of input segments -> how many times their pieces crossed
  std::vector<Piece> pending_;
  std::vector<Pair> crossed_;
  std::deque<Pair> queue_;
  std::vector<Pair> created_;
  std::vector<HalfEdge> stack_;
  std::size_t steiner_ = 0;
  std::size_t splits_ = 0;
};

}  // namespace meshstep
