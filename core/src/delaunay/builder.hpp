// The triangulation pipeline shared by triangulate() and refine(): validation, scaling,
// insertion order, vertices, segments, removal of holes and outside, and conversion to
// plain arrays. Internal to the core library.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "meshstep/delaunay/invariants.hpp"
#include "meshstep/delaunay/segment_insertion.hpp"
#include "meshstep/delaunay/spatial_sort.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/error.hpp"
#include "meshstep/geometry/magnitudes.hpp"
#include "meshstep/huge_pages.hpp"
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/release.hpp"

namespace meshstep::detail {

inline std::string vertex_name(const Pslg& in, std::size_t i) {
  return "vertex " + std::to_string(i + in.first_index);
}

inline void validate_magnitudes(const Pslg& in);

using io::shortest_text;

inline void validate(const Pslg& in) {
  for (std::size_t i = 0; i < in.points.size(); ++i)
    if (!std::isfinite(in.points[i].x) || !std::isfinite(in.points[i].y))
      throw InputError(vertex_name(in, i) + " has a coordinate that is not a finite number");
  validate_magnitudes(in);
  for (std::size_t s = 0; s < in.segments.size(); ++s) {
    const Segment& seg = in.segments[s];
    if (seg.a >= in.points.size() || seg.b >= in.points.size())
      throw InputError("segment " + std::to_string(s + in.first_index) +
                       " names a vertex that does not exist");
  }
  for (const Point& p : in.holes)
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw InputError("a hole point has a coordinate that is not a finite number");
}

// Scaling by 2^scale_exponent() brings the input into the window where the predicates are
// exact (geometry/magnitudes.hpp); the output is unscaled bit for bit.
inline int scale_exponent(const Pslg& in) { return magnitudes(in.points).scale_exponent(); }

// The rule: the nonzero |coordinates| of the vertices, hole and region points must lie
// within a factor 2^kSpanExponent (about 1.4e42) of each other. Beyond it, exact
// predicates would need arbitrary-precision arithmetic; such inputs (a coordinate of 1e-300
// among unit ones, or 1e308 among them) are refused, naming the two coordinates.
inline void validate_magnitudes(const Pslg& in) {
  // Points numbered as vertices, then holes, then regions.
  std::vector<Point> region_points;
  for (const Region& r : in.regions) region_points.push_back(r.point);
  Magnitudes m = magnitudes(in.points);
  m.merge(magnitudes(in.holes), in.points.size());
  m.merge(magnitudes(region_points), in.points.size() + in.holes.size());
  if (m.within_span()) return;
  const auto point = [&](std::size_t i) -> const Point& {
    if (i < in.points.size()) return in.points[i];
    if (i < in.points.size() + in.holes.size()) return in.holes[i - in.points.size()];
    return region_points[i - in.points.size() - in.holes.size()];
  };
  const auto name = [&](std::size_t i) {
    const std::size_t holes_from = in.points.size(), regions_from = holes_from + in.holes.size();
    if (i < holes_from) return vertex_name(in, i);
    if (i < regions_from) return "hole point " + std::to_string(i - holes_from + in.first_index);
    return "region point " + std::to_string(i - regions_from + in.first_index);
  };
  const auto at = [&](std::size_t i) {
    return " (" + shortest_text(point(i).x) + ", " + shortest_text(point(i).y) + ")";
  };
  // The two coordinates themselves: the smallest nonzero one and the largest.
  const Point& lo = point(m.smallest_at);
  const Point& hi = point(m.largest_at);
  const double small = lo.x != 0.0 && (lo.y == 0.0 || std::abs(lo.x) <= std::abs(lo.y)) ? lo.x : lo.y;
  const double large = std::abs(hi.x) >= std::abs(hi.y) ? hi.x : hi.y;
  const std::string of_small = m.smallest_at == m.largest_at ? "" : " of " + name(m.smallest_at) + at(m.smallest_at);
  throw InputError("coordinates too far apart in magnitude: " + shortest_text(small) + of_small + " is more than 2^" +
                   std::to_string(kSpanExponent) + " (about 1e42) times smaller than " + shortest_text(large) +
                   " of " + name(m.largest_at) + at(m.largest_at) +
                   "; meshstep computes exactly only within that span (is one of them a typo, or in other units?)");
}

inline void scale_points(std::vector<Point>& points, int e) {
  if (e == 0) return;
  for (Point& p : points) p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
}

// The input points, scaled, in insertion order (BRIO rounds along the Hilbert curve): the triangulation numbers its vertices in
// insertion order, so that consecutive insertions touch neighbouring memory. input_of[i]
// is the input index of internal vertex i.
struct SortedPoints {
  std::vector<Point> points;
  std::vector<std::uint32_t> input_of;
};

inline SortedPoints sort_points(Pslg& in, int exponent) {
  SortedPoints sorted;
  sorted.input_of = brio_order(in.points);
  resize_huge(sorted.points, in.points.size());
  for (std::size_t i = 0; i < sorted.input_of.size(); ++i) sorted.points[i] = in.points[sorted.input_of[i]];
  release(in.points);  // the triangulation owns the points now
  scale_points(sorted.points, exponent);
  return sorted;
}

template <TriangleMesh Mesh, class Rec>
class Builder {
 public:
  Builder(Pslg& in, const TriangulateOptions& options, TriangulateReport& report, Rec rec)
      : Builder(in, options, report, std::move(rec), scale_exponent(in)) {}

  TriMesh run() {
    build();
    return finish();
  }

  // Vertices, segments and carving: the (constrained) Delaunay triangulation of the domain,
  // left in triangulation() for an algorithm to continue on.
  void build() {
    Rec& rec = tri_.recorder();
    if constexpr (Rec::enabled) rec.set_vertex_context(input_of_, exponent_);
    rec.phase_begin(replay::Phase::insert_vertices);
    tri_.insert_all();
    rec.phase_end(replay::Phase::insert_vertices);
    const std::size_t input_count = input_count_;
    if (!in_.segments.empty()) {
      rec.phase_begin(replay::Phase::recover_segments);
      std::vector<VertexId> internal_of(input_count);
      for (VertexId i = 0; i < input_count; ++i) internal_of[input_of_[i]] = i;
      for (std::size_t i = 0; i < in_.segments.size(); ++i) {
        const Segment& s = in_.segments[i];
        const VertexId a = representative(internal_of[s.a]), b = representative(internal_of[s.b]);
        if (a != b) segments_.insert(a, b, s.marker, static_cast<std::uint32_t>(i));
      }
      rec.phase_end(replay::Phase::recover_segments);
    }
    report_.duplicate_vertices = tri_.duplicate_count();
    report_.steiner_vertices = tri_.points().size() - input_count;
    report_.split_segments = segments_.split_count();
    report_.mesh_bytes = tri_.mesh().memory_bytes();
    check_whole_triangulation(tri_);
    rec.phase_begin(replay::Phase::carve);
    rec.step_begin(tri_.mesh(), replay::StepKind::carve);
    carve();
    rec.phase_end(replay::Phase::carve);
    built_vertices_ = tri_.points().size();
  }

  // Ends the recording and converts the mesh (releasing the data structure).
  TriMesh finish() {
    tri_.recorder().run_end(tri_.mesh());
    prefer_first_duplicates();
    if (report_.duplicate_vertices > 0) report_.warnings.push_back(duplicate_warning());
    report_.vertices = tri_.points().size() - tri_.removed_vertices().size();
    report_.triangles = tri_.mesh().face_count();
    report_.segments = kept_segments_.size() + new_boundary_.size();
    if (!options_.keep_mesh && !changed_after_build_) return {};
    return to_tri_mesh();
  }

  Triangulation<Mesh, Rec>& triangulation() { return tri_; }
  std::size_t input_count() const { return input_count_; }
  int exponent() const { return exponent_; }  // coordinates are scaled by 2^exponent
  // The domain's boundary after build(): the input segments that bound a triangle, with their
  // markers, then the unconstrained edges carving made boundary (marker 1).
  std::vector<Segment> boundary_segments() const {
    std::vector<Segment> all = kept_segments_;
    for (const auto& [a, b] : new_boundary_) all.push_back({a, b, 1});
    return all;
  }
  // After an algorithm changed the faces: the region attributes again, each region flooded
  // from the live face that holds its point (the faces are new, and some reuse slots that
  // carving emptied, so nothing of the first assignment carries over).
  void reassign_regions() {
    if (in_.regions.empty()) return;
    const Mesh& m = tri_.mesh();
    attribute_.assign(m.face_capacity(), 0.0);
    max_area_.assign(m.face_capacity(), -1.0);
    std::vector<std::uint32_t> region_of(m.face_capacity(), 0);
    for (std::size_t i = 0; i < in_.regions.size(); ++i) {
      const Region& r = in_.regions[i];
      const FaceId f = live_face_holding(scaled(r.point));
      if (f == kNone) continue;
      flood(f, region_of, static_cast<std::uint32_t>(i + 1), [&](FaceId g) {
        attribute_[g] = r.attribute;
        max_area_[g] = r.max_area;
      });
    }
  }

  // The regions' area bounds over the current faces (scaled like the points), for an
  // algorithm that refines to them; empty when no region has one.
  template <class Field>
  void region_area_field(Field& field) const {
    if (max_area_.empty()) return;
    const Mesh& m = tri_.mesh();
    for (FaceId f = 0; f < m.face_capacity(); ++f) {
      if (!m.is_live(f) || f >= max_area_.size() || !(max_area_[f] > 0.0)) continue;
      const HalfEdge h = m.half_edge(f);
      field.add(tri_.point(m.origin(h)), tri_.point(m.dest(h)), tri_.point(m.apex(h)),
                std::ldexp(max_area_[f], 2 * exponent_));
    }
    field.build();
  }

  // An algorithm that ran on triangulation() gives the boundary back, split as it left it;
  // the output then checks every triangle again (to_tri_mesh).
  void set_boundary_segments(std::vector<Segment> segments) {
    kept_segments_ = std::move(segments);
    new_boundary_.clear();
    changed_after_build_ = true;
  }
  const Pslg& input() const { return in_; }

 private:
  Builder(Pslg& in, const TriangulateOptions& options, TriangulateReport& report, Rec rec,
          int exponent)
      : Builder(in, options, report, std::move(rec), exponent, sort_points(in, exponent)) {}
  Builder(Pslg& in, const TriangulateOptions& options, TriangulateReport& report, Rec rec,
          int exponent, SortedPoints sorted)
      : in_(in), options_(options), report_(report), exponent_(exponent),
        input_count_(sorted.points.size()), input_of_(std::move(sorted.input_of)),
        tri_(std::move(sorted.points), options.insertion, std::move(rec)), segments_(tri_) {}

  // Input numbering of an internal vertex. Steiner vertices follow the input's in the order
  // they were made, closing the gaps that removed ones leave.
  std::uint32_t external(VertexId v) const {
    if (v < input_count_) return input_of_[v];
    return steiner_index_.empty() ? v : steiner_index_[v - input_count_];
  }
  // Numbers the Steiner vertices that remain, when some were removed.
  void number_steiner_vertices() {
    if (tri_.removed_vertices().empty()) return;
    const std::size_t count = tri_.points().size() - input_count_;
    std::vector<std::uint8_t> removed(count, 0);
    for (const VertexId v : tri_.removed_vertices()) removed[v - input_count_] = 1;
    steiner_index_.assign(count, kNone);
    std::uint32_t next = static_cast<std::uint32_t>(input_count_);
    for (std::size_t i = 0; i < count; ++i)
      if (!removed[i]) steiner_index_[i] = next++;
  }

  // Duplicates are merged into whichever copy was inserted first, which the shuffled
  // insertion order makes arbitrary: let the output use the copy that comes first in the
  // input instead, as Triangle does.
  void prefer_first_duplicates() {
    if (tri_.duplicate_count() == 0) return;
    for (VertexId v = 0; v < input_count_; ++v) {
      const VertexId r = tri_.merged_into(v);
      if (r != kNone && input_of_[v] < input_of_[r]) std::swap(input_of_[v], input_of_[r]);
    }
  }

  // "3 duplicate vertices merged (e.g. vertex 9 is at the same place as vertex 2)", in the
  // input's numbering, naming the duplicate that comes first in the input.
  std::string duplicate_warning() const {
    std::uint32_t dup = kNoIndex, kept = kNoIndex;
    for (VertexId v = 0; v < input_count_; ++v) {
      const VertexId r = tri_.merged_into(v);
      if (r != kNone && input_of_[v] < dup) {
        dup = input_of_[v];
        kept = input_of_[r];
      }
    }
    const auto name = [&](std::uint32_t i) { return "vertex " + std::to_string(i + in_.first_index); };
    return std::to_string(report_.duplicate_vertices) + " duplicate vertices merged (e.g. " +
           name(dup) + " is at the same place as " + name(kept) + ")";
  }

  VertexId representative(VertexId v) const {
    const VertexId m = tri_.merged_into(v);
    return m == kNone ? v : m;
  }

  Point scaled(const Point& p) const { return {std::ldexp(p.x, exponent_), std::ldexp(p.y, exponent_)}; }

  // A live face whose closed triangle holds p, by looking at every face (kNone: outside the
  // domain). For the few region points, on a carved mesh that a walk could leave.
  FaceId live_face_holding(const Point& p) const {
    const Mesh& m = tri_.mesh();
    for (FaceId f = 0; f < m.face_capacity(); ++f) {
      if (!m.is_live(f)) continue;
      const HalfEdge h = m.half_edge(f);
      const Point &a = tri_.point(m.origin(h)), &b = tri_.point(m.dest(h)), &c = tri_.point(m.apex(h));
      if (orient2d(a, b, p) >= 0.0 && orient2d(b, c, p) >= 0.0 && orient2d(c, a, p) >= 0.0) return f;
    }
    return kNone;
  }

  // The face holding p (a hole or region point), found by walking from any live face.
  FaceId face_at(const Point& p) const {
    const Mesh& m = tri_.mesh();
    FaceId start = 0;
    while (!m.is_live(start)) ++start;
    return m.face(tri_.locate(scaled(p), m.half_edge(start)).half_edge);
  }

  // Visits the faces reachable from `seed` without crossing a constrained edge whose
  // stamp is not yet `stamp`, and stamps them.
  template <class Visit>
  void flood(FaceId seed, std::vector<std::uint32_t>& stamps, std::uint32_t stamp, Visit&& visit) {
    const Mesh& m = tri_.mesh();
    if (stamps[seed] == stamp) return;
    stack_.clear();
    stack_.push_back(seed);
    stamps[seed] = stamp;
    while (!stack_.empty()) {
      const FaceId f = stack_.back();
      stack_.pop_back();
      visit(f);
      const HalfEdge first = m.half_edge(f);
      for (HalfEdge h : {first, m.next(first), m.prev(first)}) {
        if (m.is_constrained(h)) continue;
        const HalfEdge t = m.twin(h);
        if (t == kNone) continue;
        const FaceId g = m.face(t);
        if (stamps[g] != stamp) {
          stamps[g] = stamp;
          stack_.push_back(g);
        }
      }
    }
  }

  // Removes the ghost faces, the faces of holes and, unless convex_hull (or when there are
  // no segments), every face reachable from outside without crossing a segment. Records the
  // unconstrained edges that become boundary, for the output's segment list.
  void carve() {
    Mesh& m = tri_.mesh();
    std::vector<FaceId> ghosts;
    const HalfEdge around_infinity = m.vertex_half_edge(kInfiniteVertex);
    for (HalfEdge h = around_infinity;;) {
      ghosts.push_back(m.face(h));
      h = m.twin(m.prev(h));
      if (h == around_infinity) break;
    }
    std::vector<std::uint32_t> dead(m.face_capacity(), 0);
    std::vector<FaceId> removed;
    std::vector<replay::RemoveReason> reasons;  // why each face goes (for the recording)
    auto reason = replay::RemoveReason::outside;
    const auto remove = [&](FaceId f) {
      removed.push_back(f);
      reasons.push_back(tri_.is_ghost(f) ? replay::RemoveReason::ghost : reason);
    };
    const bool eat_outside = !options_.convex_hull && !in_.segments.empty();
    for (const FaceId f : ghosts) {
      if (eat_outside) {
        flood(f, dead, 1, remove);
      } else if (!dead[f]) {
        dead[f] = 1;
        remove(f);
      }
    }
    reason = replay::RemoveReason::hole;
    for (const Point& hole : in_.holes) flood(face_at(hole), dead, 1, remove);
    assign_regions(dead);

    // Constrained edges that keep a triangle on at least one side, decided while the mesh
    // is still closed (afterwards a vertex where two parts of the domain touch has two
    // separate fans, and an edge search from it could miss one).
    for (const auto& [key, constraint] : segments_.constraints()) {
      const auto a = static_cast<VertexId>(key >> 32), b = static_cast<VertexId>(key & 0xFFFFFFFFu);
      const HalfEdge h = tri_.find_edge(a, b);
      if (h != kNone && (!dead[m.face(h)] || !dead[m.face(m.twin(h))]))
        kept_segments_.push_back({a, b, constraint.marker});
    }
    for (const FaceId f : removed) {
      const HalfEdge first = m.half_edge(f);
      for (HalfEdge h : {first, m.next(first), m.prev(first)}) {
        const HalfEdge t = m.twin(h);
        if (t != kNone && !dead[m.face(t)] && !m.is_constrained(t))
          new_boundary_.push_back({m.origin(t), m.dest(t)});
      }
    }
    report_.removed_triangles = removed.size() - ghosts.size();  // ghosts are always among them
    for (std::size_t i = 0; i < removed.size(); ++i) tri_.remove_face(removed[i], reasons[i]);
    m.rebuild_vertex_half_edges();
  }

  void assign_regions(const std::vector<std::uint32_t>& dead) {
    if (in_.regions.empty()) return;
    const std::size_t capacity = tri_.mesh().face_capacity();
    attribute_.assign(capacity, 0.0);
    max_area_.assign(capacity, -1.0);
    std::vector<std::uint32_t> region_of(capacity, 0);
    for (std::size_t i = 0; i < in_.regions.size(); ++i) {
      const Region& r = in_.regions[i];
      const FaceId f = face_at(r.point);
      if (dead[f]) continue;
      flood(f, region_of, static_cast<std::uint32_t>(i + 1), [&](FaceId g) {
        attribute_[g] = r.attribute;
        max_area_[g] = r.max_area;
      });
    }
  }

  TriMesh to_tri_mesh() {
    number_steiner_vertices();
    const Mesh& m = tri_.mesh();
    const std::size_t vertex_count = tri_.points().size() - tri_.removed_vertices().size();
    TriMesh out;
    out.first_index = in_.first_index;
    out.input_vertex_count = input_count_;
    out.holes = in_.holes;
    out.regions = in_.regions;
    out.has_segment_markers = in_.has_segment_markers;

    // The cheap checks again when an algorithm changed the mesh after build() checked it
    // (carving only removes faces): every triangle counterclockwise, exactly, in the scaled
    // coordinates, and every vertex added after carving the corner of a triangle (a crossing
    // point of two segments outside the domain need not be: it went with the outside).
    const bool check = changed_after_build_;
    std::vector<std::uint8_t> cornered(check ? tri_.points().size() : 0, 0);
    if (check) {
      std::fill(cornered.begin(), cornered.begin() + static_cast<std::ptrdiff_t>(built_vertices_), 1);
      for (const VertexId v : tri_.removed_vertices()) cornered[v] = 1;
    }
    std::vector<std::uint32_t> index_of;
    if (options_.compute_neighbors) index_of.assign(m.face_capacity(), kNoIndex);
    // Nothing below crosses an edge unless neighbours are wanted: the adjacency goes before
    // the triangles are allocated (at 1e6 points, 28 of the peak's 116 MB).
    if (!options_.compute_neighbors) tri_.mesh().drop_adjacency();
    reserve_huge(out.triangles, m.face_count());
    for (FaceId f = 0; f < m.face_capacity(); ++f) {
      if (!m.is_live(f)) continue;
      const HalfEdge h = m.half_edge(f);
      if (options_.compute_neighbors) index_of[f] = static_cast<std::uint32_t>(out.triangles.size());
      const VertexId a = m.origin(h), b = m.dest(h), c = m.apex(h);
      if (check) {
        if (!(orient2d(tri_.point(a), tri_.point(b), tri_.point(c)) > 0.0))
          throw std::logic_error("the mesh made has a triangle that is not counterclockwise (face " + std::to_string(f) + ")");
        cornered[a] = cornered[b] = cornered[c] = 1;
      }
      out.triangles.push_back({external(a), external(b), external(c)});
      if (!in_.regions.empty()) {
        out.triangle_attributes.push_back(attribute_[f]);
        out.triangle_max_area.push_back(max_area_[f]);
      }
    }
    if (const auto lost = std::find(cornered.begin(), cornered.end(), 0); lost != cornered.end())
      throw std::logic_error("the mesh made has a vertex in no triangle (vertex " +
                             std::to_string(lost - cornered.begin()) + ", added after carving)");
    if (!in_.regions.empty()) out.attributes_per_triangle = 1;
    if (options_.compute_neighbors) {
      out.neighbors.reserve(out.triangles.size());
      for (FaceId f = 0; f < m.face_capacity(); ++f) {
        if (!m.is_live(f)) continue;
        const HalfEdge h = m.half_edge(f);
        std::array<std::uint32_t, 3> n{};
        // Neighbour i lies across the edge opposite vertex i: edges next(h), prev(h), h.
        const HalfEdge opposite[3] = {m.next(h), m.prev(h), h};
        for (int i = 0; i < 3; ++i) {
          const HalfEdge t = m.twin(opposite[i]);
          n[i] = t == kNone ? kNoIndex : index_of[m.face(t)];
        }
        out.neighbors.push_back(n);
      }
    }
    // Segments: the constrained edges that still bound a triangle, and the unconstrained
    // edges that carving turned into boundary (convex hull edges of a point set), marker 1.
    // Each from its smaller vertex index to its larger, sorted: one order whatever the path
    // (a replay of the run writes the same list, replay/output_mesh.cpp).
    const auto add_segment = [&](VertexId a, VertexId b, int marker) {
      const std::uint32_t i = external(a), j = external(b);
      out.segments.push_back({std::min(i, j), std::max(i, j), marker});
    };
    for (const Segment& s : kept_segments_) add_segment(s.a, s.b, s.marker);
    for (const auto& [a, b] : new_boundary_) add_segment(a, b, 1);
    std::sort(out.segments.begin(), out.segments.end(),
              [](const Segment& s, const Segment& t) { return std::pair(s.a, s.b) < std::pair(t.a, t.b); });

    // The vertices last, once the mesh is released: a lower peak for large inputs.
    tri_.mesh() = Mesh{};
    resize_huge(out.points, vertex_count);
    for (VertexId v = 0; v < tri_.points().size(); ++v)
      if (const std::uint32_t i = external(v); i != kNone) out.points[i] = tri_.point(v);
    scale_points(out.points, -exponent_);
    out.attributes_per_vertex = in_.attributes_per_vertex;
    out.vertex_attributes = std::move(in_.vertex_attributes);
    out.vertex_attributes.resize(vertex_count * out.attributes_per_vertex, 0.0);
    if (in_.has_vertex_markers) set_vertex_markers(out, std::move(in_.vertex_markers), input_count_);
    return out;
  }

  Pslg& in_;
  const TriangulateOptions& options_;
  TriangulateReport& report_;
  int exponent_;
  std::size_t input_count_;
  std::size_t built_vertices_ = 0;  // the vertices when carving ended (to_tri_mesh checks the later ones)
  bool changed_after_build_ = false;  // an algorithm ran after build()
  std::vector<std::uint32_t> input_of_;
  std::vector<std::uint32_t> steiner_index_;  // by Steiner vertex: its output index (kNone: removed)
  Triangulation<Mesh, Rec> tri_;
  SegmentInserter<Mesh, Rec> segments_;
  std::vector<FaceId> stack_;
  std::vector<double> attribute_, max_area_;
  std::vector<std::pair<VertexId, VertexId>> new_boundary_;
  std::vector<Segment> kept_segments_;
};

}  // namespace meshstep::detail
