// Delaunay refinement on a carved constrained Delaunay triangulation (Ruppert, Chew,
// Shewchuk's Triangle, Ungor's off-centers), over any TriangleMesh and recording policy.
//
// Loop: split every encroached subsegment first; then take the bad triangle with the
// shortest shortest edge (Triangle's order; worst angle first or FIFO on request), select
// its point, walk to it from the triangle. If the walk is blocked by a segment, or the point
// lies inside the diametral circle (or lens) of a segment on the boundary of its cavity, the
// point is rejected and those segments are split instead; otherwise it is inserted. New
// faces are checked as they appear, so the queue holds every bad triangle at all times.
//
// Segment splits use concentric shells where segments meet: a subsegment that shares an end
// with another segment in a triangle beside it is split at a power-of-two distance from
// that end, so that splits on two segments meeting at a small angle stay at matching
// distances and do not chase each other (Ruppert's "modified segment splitting", decided
// locally as Triangle does); any other subsegment at its midpoint. A bad triangle whose
// smallest angle sits between two segments cannot be improved (the angle is the input's)
// and is skipped.
//
// Works in the triangulation's scaled coordinates (triangulate's exact power-of-two scaling):
// angles do not change, and the caller scales area and size bounds.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <deque>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/huge_array.hpp"
#include "meshstep/huge_pages.hpp"
#include "meshstep/refine/lepp.hpp"
#include "meshstep/refine/quality.hpp"
#include "meshstep/refine/refine.hpp"
#include "improvement.hpp"
#include "mesh_queries.hpp"
#include "scaled_criteria.hpp"

namespace meshstep::detail {

template <TriangleMesh Mesh, class Rec>
class Refiner {
 public:
  // The criteria come with set_criteria(), before each run().
  Refiner(Triangulation<Mesh, Rec>& tri, const std::vector<Segment>& boundary, std::size_t input_count,
          const RefineOptions& options)
      : tri_(tri), mesh_(tri.mesh()), input_count_(input_count), options_(options),
        exact_range_(std::span<const Point>(tri.points()).first(input_count)) {
    for (const Segment& s : boundary) subsegments_[key(s.a, s.b)] = {s.marker, s.a, s.b};
    on_segment_.assign(tri_.points().size(), {kNone, kNone});
    find_small_input_angles(boundary);
  }

  // The criteria of the next run() (a run in phases changes them between runs).
  void set_criteria(const ScaledCriteria& criteria) { criteria_ = criteria; }

  void run(RefineReport& report) {
    Rec& rec = tri_.recorder();
    clear_queues();  // what a capped phase left: the next phase checks every face again
    rec.phase_begin(replay::Phase::refine);
    // Every segment and boundary edge is a suspect once; every face is checked once. In an
    // order of the mesh's own (vertex ids), not of the data structure's slots: every data
    // structure and insertion then refines alike.
    std::vector<FaceId> faces;
    for (FaceId f = 0; f < mesh_.face_capacity(); ++f) {
      if (!mesh_.is_live(f)) continue;
      faces.push_back(f);
      const HalfEdge first = mesh_.half_edge(f);
      for (const HalfEdge h : {first, mesh_.next(first), mesh_.prev(first)})
        if (is_segment(h) && (mesh_.twin(h) == kNone || mesh_.origin(h) < mesh_.dest(h)) && beside_region(h))
          segments_.push_back({mesh_.origin(h), mesh_.dest(h), h});
    }
    sort_suspects(segments_.begin(), segments_.end());
    check_faces(faces);
    ProgressClock clock(options_.progress, 4096);
    for (std::uint64_t round = 1; !capped(); ++round) {
      clock.tick(round, [&] {
        return RefineProgress{tri_.points().size() - input_count_, mesh_.face_count(), queued() + segments_.size()};
      });
      if (!segments_.empty()) {
        const Suspect suspect = segments_.back();
        segments_.pop_back();
        const HalfEdge h = find_segment(suspect);
        // A segment kept whole stays encroached: the mesh is constrained Delaunay there.
        if (h != kNone && may_split(h) && encroached_by_apex(h)) split_segment(h, kNone, nullptr);
        continue;
      }
      Candidate c;
      if (!pop_bad(c)) break;
      if (!still_there(c)) continue;
      fix(c);
    }
    rec.phase_end(replay::Phase::refine);
    if (options_.improve && !capped()) {
      removed_ += remove_steiner_vertices(tri_, input_count_, [&](const auto& before, const auto& after) {
        return removal_improves(before, after);
      });
    } else if (options_.improve) {
      // Capped: no improvement, but its phase all the same (empty), so that a log's phases
      // follow from its operations alone (replay/run_header.hpp).
      rec.phase_begin(replay::Phase::improve);
      rec.phase_end(replay::Phase::improve);
    }
    report.removed_vertices = removed_;
    report.segment_splits = segment_splits_;
    report.triangles_split = triangles_split_;
    report.rejected_points = rejected_;
    report.unsplittable_segments = unsplittable_;
    report.points_out_of_range = out_of_range_;
    report.kept_segment_refusals = kept_refusals_;
    report.stopped_by_cap = capped();
    assess(report);
  }

  // The boundary after the run: every subsegment with its segment's marker.
  std::vector<Segment> boundary() const {
    std::vector<Segment> out;
    out.reserve(subsegments_.size());
    for (const auto& [k, info] : subsegments_)
      out.push_back({static_cast<std::uint32_t>(k >> 32), static_cast<std::uint32_t>(k & 0xFFFFFFFFu), info.marker});
    return out;
  }

 private:
  // What a subsegment belongs to: its segment's marker and the segment's two ends.
  struct SubsegmentInfo {
    int marker;
    VertexId a, b;
  };

  // A subsegment to check for encroachment: its ends, and a half-edge that held it.
  struct Suspect {
    VertexId a, b;
    HalfEdge hint;
  };

  // A bad triangle waiting in the queue: its slot and its vertices, to tell whether it is
  // still there when its turn comes. 16 bytes: the queue holds most of a mesh under an
  // area bound (790k of 1.3M triangles on A.poly), so each byte counts.
  struct Candidate {
    FaceId face;
    VertexId a, b, c;
    std::array<VertexId, 3> key() const {
      std::array<VertexId, 3> k{a, b, c};
      std::sort(k.begin(), k.end());
      return k;
    }
  };

  // The half-edge of f leaving its smallest vertex id: shapes are measured from it, so that
  // ties between equal edges (isosceles triangles are everywhere after midpoint splits) fall
  // the same way whichever vertex the data structure lists first.
  HalfEdge first_edge(FaceId f) const { return detail::first_edge(mesh_, f); }

  std::array<VertexId, 3> face_key(FaceId f) const {
    const HalfEdge h = mesh_.half_edge(f);
    std::array<VertexId, 3> k{mesh_.origin(h), mesh_.dest(h), mesh_.apex(h)};
    std::sort(k.begin(), k.end());
    return k;
  }

  // Checks faces in the order of their vertex ids.
  void check_faces(std::vector<FaceId>& faces) {
    std::sort(faces.begin(), faces.end(), [&](FaceId f, FaceId g) { return face_key(f) < face_key(g); });
    for (const FaceId f : faces) check_face(f);
  }

  template <class It>
  static void sort_suspects(It begin, It end) {
    std::sort(begin, end, [](const Suspect& s, const Suspect& t) { return key(s.a, s.b) < key(t.a, t.b); });
  }

  static std::uint64_t key(VertexId a, VertexId b) { return edge_tie_key(a, b); }

  bool is_segment(HalfEdge h) const { return mesh_.twin(h) == kNone || mesh_.is_constrained(h); }

  // May the segment of h be split (RefineOptions::segment_splits)? One with no triangle on
  // its other side lies on the domain's boundary (the outer one or a hole's).
  bool may_split(HalfEdge h) const {
    switch (options_.segment_splits) {
      case SegmentSplits::all: return true;
      case SegmentSplits::interior: return mesh_.twin(h) != kNone;
      case SegmentSplits::none: return false;
    }
    return true;
  }

  bool face_in_region(HalfEdge h) const {
    return in_region(criteria_, point(mesh_.origin(h)), point(mesh_.dest(h)), point(mesh_.apex(h)));
  }
  // Is a triangle on either side of h in the region? Only such segments are suspects at the
  // start of a run: one encroached far away is the rest of the mesh's, which keeps what it
  // had (a new vertex that encroaches on it gets it split all the same).
  bool beside_region(HalfEdge h) const {
    if (!criteria_.region || face_in_region(h)) return true;
    const HalfEdge t = mesh_.twin(h);
    return t != kNone && face_in_region(t);
  }
  const Point& point(VertexId v) const { return tri_.point(v); }

  bool capped() const { return reached_cap(criteria_, tri_.points().size() - input_count_, mesh_); }

  // The half-edge of subsegment a-b if it still is one: the hint if it still holds it, else
  // a search around either end (a vertex where two parts of the domain touch has two fans,
  // and a search from one end can miss the other fan).
  HalfEdge find_segment(const Suspect& s) const {
    const auto holds = [&](HalfEdge h) {
      return h != kNone && mesh_.is_live(mesh_.face(h)) &&
             ((mesh_.origin(h) == s.a && mesh_.dest(h) == s.b) || (mesh_.origin(h) == s.b && mesh_.dest(h) == s.a));
    };
    HalfEdge h = s.hint;
    if (!holds(h)) h = tri_.find_edge(s.a, s.b);
    if (!holds(h)) h = tri_.find_edge(s.b, s.a);
    return holds(h) && is_segment(h) ? h : kNone;
  }

  // Is p strictly inside the circle with diameter a-b (the angle a-p-b over 90 degrees)?
  bool in_diametral_circle(const Point& p, VertexId a, VertexId b) const {
    const Point &pa = point(a), &pb = point(b);
    return (pa.x - p.x) * (pb.x - p.x) + (pa.y - p.y) * (pb.y - p.y) < 0.0;
  }

  // Does p encroach on the segment a-b?
  bool encroaches(const Point& p, VertexId a, VertexId b) const {
    if (options_.encroachment == Encroachment::circle) return in_diametral_circle(p, a, b);
    const Point &pa = point(a), &pb = point(b);
    const double ax = pa.x - p.x, ay = pa.y - p.y, bx = pb.x - p.x, by = pb.y - p.y;
    const double dot = ax * bx + ay * by;
    return dot < 0.0 && dot * dot >= criteria_.lens_cos2 * (ax * ax + ay * ay) * (bx * bx + by * by);
  }

  // In a constrained Delaunay triangulation a segment is encroached when a vertex of the
  // triangle on either side of it is.
  bool encroached_by_apex(HalfEdge h) const {
    const VertexId a = mesh_.origin(h), b = mesh_.dest(h);
    if (encroaches(point(mesh_.apex(h)), a, b)) return true;
    const HalfEdge t = mesh_.twin(h);
    return t != kNone && encroaches(point(mesh_.apex(t)), a, b);
  }

  // Does a triangle of shape s miss an angle or aspect bound?
  bool angle_bad(const quality::Shape& s) const {
    return misses_min_angle(criteria_, s) || misses_max_angle(criteria_, s) || misses_max_aspect(criteria_, s);
  }

  // Is face f bad, and if so with what priority? Skips (and counts) the ones whose smallest
  // angle lies between two segments when only the angle bounds fail.
  void check_face(FaceId f) {
    const HalfEdge h = first_edge(f);
    const VertexId a = mesh_.origin(h), b = mesh_.dest(h), c = mesh_.apex(h);
    const quality::Shape s = quality::shape(point(a), point(b), point(c));
    const bool angle_bad = this->angle_bad(s);
    const bool size_bad = too_large(criteria_, s, point(a), point(b), point(c));
    if (!angle_bad && !size_bad) return;
    // After the bounds, which pass most triangles for less than a polygon's test costs.
    if (!in_region(criteria_, point(a), point(b), point(c))) return;
    if (!size_bad && cannot_improve(h, s)) return;
    push_bad(priority(s), {f, a, b, c});
  }

  // Triangles refinement leaves alone when only their angles are bad: the smallest angle
  // lies between two segments (it is the input's), or the shortest edge spans a small input
  // angle on a shell: its ends lie on two segments meeting there at under 60 degrees, at the
  // same distance from the apex. A vertex inside would only split both segments on a shell
  // closer to the apex, and so on without end. At different distances the shortest edge is
  // not the shells' doing, and splitting does fix it (earcut.poly: a 21.5-degree triangle
  // by a 48-degree corner was left alone before this distinction).
  bool cannot_improve(HalfEdge h, const quality::Shape& s) const {
    HalfEdge e = h;
    for (int i = 0; i < s.shortest_edge; ++i) e = mesh_.next(e);
    if (is_segment(mesh_.next(e)) && is_segment(mesh_.prev(e))) return true;
    const VertexId u = mesh_.origin(e), w = mesh_.dest(e);
    const auto& p = on_segment_[u];
    const auto& q = on_segment_[w];
    if (p.first == kNone || q.first == kNone || p == q) return false;
    const VertexId r = mesh_.apex(e);
    for (const VertexId apex : {p.first, p.second})
      if ((apex == q.first || apex == q.second) && small_angle_[apex] && on_shell(u, w, r, apex)) return true;
    return false;
  }

  // Are u and w on the same shell round apex (the same distance, to within the rounding of
  // shell splits), and r no farther out than the next shell?
  bool on_shell(VertexId u, VertexId w, VertexId r, VertexId apex) const {
    const double du = quality::squared_distance(point(u), point(apex));
    const double dw = quality::squared_distance(point(w), point(apex));
    const double dr = quality::squared_distance(point(r), point(apex));
    return du < 1.002 * dw && dw < 1.002 * du && dr < 4.01 * du;
  }

  // Improvement's rule: a removal must raise the smallest angle of the triangles it
  // replaces, and every new triangle must meet the criteria (so the bounds stay met).
  template <class Triangles>
  bool removal_improves(const Triangles& before, const Triangles& after) const {
    double worst_before = 1.0;
    for (const auto& t : before)
      worst_before = std::min(worst_before, quality::shape(point(t[0]), point(t[1]), point(t[2])).sin2_min_angle());
    for (const auto& t : after) {
      const quality::Shape s = quality::shape(point(t[0]), point(t[1]), point(t[2]));
      if (s.sin2_min_angle() <= worst_before) return false;
      // Outside the region a triangle is not held to the criteria.
      if (in_region(criteria_, point(t[0]), point(t[1]), point(t[2])) &&
          (angle_bad(s) || too_large(criteria_, s, point(t[0]), point(t[1]), point(t[2]))))
        return false;
    }
    return true;
  }

  void clear_queues() {
    for (auto& bucket : buckets_) bucket.clear();
    lowest_ = kBuckets;
    fifo_.clear();
    segments_.clear();
  }

  // Smaller: sooner. The shortest edge squared, or sin^2 of the smallest angle.
  double priority(const quality::Shape& s) const {
    return options_.order == RefineOrder::smallest_first ? s.shortest2 : s.sin2_min_angle();
  }

  void push_bad(double priority, const Candidate& c) {
    if (options_.order == RefineOrder::fifo) {
      fifo_.push_back(c);
      return;
    }
    // Within a bucket the newest first, which keeps the work near the faces just made.
    const std::size_t bucket = bucket_of(priority);
    buckets_[bucket].push_back(c);
    lowest_ = std::min(lowest_, bucket);
  }
  // Smallest first: a bucket per half power of two of the shortest edge squared (its
  // exponent and whether the mantissa passes sqrt(1/2)), the whole double range. Worst
  // first: 1/1024 of the quality range, sin^2 of the smallest angle from 0 to 0.75.
  std::size_t bucket_of(double priority) const {
    if (options_.order == RefineOrder::smallest_first) {
      int e;
      const double m = std::frexp(priority, &e);  // priority = m 2^e, m in [0.5, 1), e in [-1073, 1024]
      const long k = 2L * e + (m > 0.7071067811865476) + 2146;
      return static_cast<std::size_t>(std::clamp(k, 0L, static_cast<long>(kBuckets) - 1));
    }
    return static_cast<std::size_t>(std::min(1023.0, std::max(0.0, priority) * (1024 / 0.75)));
  }

  bool pop_bad(Candidate& c) {
    if (options_.order == RefineOrder::fifo) {
      if (fifo_.empty()) return false;
      c = fifo_.front();
      fifo_.pop_front();
      return true;
    }
    while (lowest_ < kBuckets && buckets_[lowest_].empty()) ++lowest_;
    if (lowest_ == kBuckets) return false;
    c = buckets_[lowest_].back();
    buckets_[lowest_].pop_back();
    return true;
  }
  std::size_t queued() const {
    std::size_t n = fifo_.size();
    for (std::size_t b = lowest_; b < kBuckets; ++b) n += buckets_[b].size();
    return n;
  }

  // Is the candidate's triangle still in the mesh? Its slot answers, except for a triangle
  // that a segment split destroyed and its flips made again (recreated_): which slot that
  // one gets depends on the data structure, and the runs must not, so it is looked for
  // round its first vertex. Only those: a search for every stale candidate made a whole
  // run 1.2 to 1.6 times slower.
  bool still_there(Candidate& c) const {
    if (holds_triangle(mesh_, c.face, c.a, c.b, c.c)) return true;
    if (recreated_.empty() || !recreated_.contains(triangle_hash(c.key()))) return false;
    const HalfEdge h = tri_.find_edge(c.a, c.b);
    if (h == kNone || mesh_.apex(h) != c.c) return false;
    c.face = mesh_.face(h);
    return true;
  }
  static std::uint64_t triangle_hash(const std::array<VertexId, 3>& k) {
    return (std::uint64_t{k[0]} * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t{k[1]} << 32 | k[2]);
  }

  // The point a bad triangle asks for, and the alternative weighed against it.
  // `terminal`: whether it is a Lepp terminal point (else the bad triangle's own point);
  // with `lepp` false the Lepp path is not followed (the fallback in fix()).
  Point select(const Candidate& c, Point& alternative, bool lepp, bool& terminal) {
    terminal = false;
    const Point &pa = point(c.a), &pb = point(c.b), &pc = point(c.c);
    Point center = quality::circumcenter(pa, pb, pc);
    const quality::Shape s = quality::shape(pa, pb, pc);
    if (!std::isfinite(center.x) || !std::isfinite(center.y)) {
      // So flat that the circumcenter overflows (the orientation is exact, the center is not):
      // the midpoint of the longest edge, which a flat triangle of a constrained Delaunay
      // triangulation has on a segment, stands in for it.
      const Point* v[3] = {&pa, &pb, &pc};
      const Point &p = *v[s.longest_edge], &q = *v[(s.longest_edge + 1) % 3];
      center = {(p.x + q.x) / 2.0, (p.y + q.y) / 2.0};
    }
    alternative = center;
    if (lepp && lepp_selection()) {
      const Point p = lepp_point(c.face);
      if (!too_close_to_terminal_vertices(p, s.shortest2)) {
        terminal = true;
        return p;
      }
    }
    if (options_.selection == Selection::longest_edge_midpoint) {
      const Point* v[3] = {&pa, &pb, &pc};
      const Point &p = *v[s.longest_edge], &q = *v[(s.longest_edge + 1) % 3];
      return {(p.x + q.x) / 2.0, (p.y + q.y) / 2.0};
    }
    if (options_.selection == Selection::circumcenter || criteria_.offcenter_beta <= 0.0) return center;
    // Off-center: on the bisector of the shortest edge pq, at the apex of the isosceles
    // triangle over pq whose radius-edge ratio is exactly the bound, when that is closer
    // to pq than the circumcenter (Ungor 2004).
    const Point* v[3] = {&pa, &pb, &pc};
    const Point &p = *v[s.shortest_edge], &q = *v[(s.shortest_edge + 1) % 3];
    const Point m{(p.x + q.x) / 2.0, (p.y + q.y) / 2.0};
    const double l = std::sqrt(s.shortest2), beta = criteria_.offcenter_beta;
    // 5% short of the apex whose triangle is exactly at the bound, as Triangle does: at the
    // bound itself, rounding leaves some new triangles a hair below it, and they come back.
    const double h = 0.95 * l * (beta + std::sqrt(beta * beta - 0.25));
    const double dx = center.x - m.x, dy = center.y - m.y, dm = std::sqrt(dx * dx + dy * dy);
    if (!(dm > 0.0)) return center;
    const Point offcenter{m.x + dx * h / dm, m.y + dy * h / dm};
    // The point not taken is the alternative the record shows beside the one taken.
    if (!(dm > h)) {
      alternative = offcenter;
      return center;
    }
    return offcenter;
  }

  // A terminal point nearer a terminal triangle's vertex than the bad triangle's shortest
  // edge (a terminal triangle so flat, next to a segment, that its centroid hugs a vertex)
  // would only make smaller triangles there, and so on down to the precision floor: the
  // bad triangle's own point is used instead.
  bool too_close_to_terminal_vertices(const Point& p, double shortest2) const {
    for (std::size_t i = lepp_faces_.size() >= 2 ? lepp_faces_.size() - 2 : 0; i < lepp_faces_.size(); ++i) {
      const HalfEdge h = mesh_.half_edge(lepp_faces_[i]);
      for (const VertexId v : {mesh_.origin(h), mesh_.dest(h), mesh_.apex(h)})
        if (quality::squared_distance(p, point(v)) < shortest2) return true;
    }
    return false;
  }

  bool lepp_selection() const {
    return options_.selection == Selection::lepp_midpoint || options_.selection == Selection::lepp_centroid;
  }

  HalfEdge lepp(FaceId f) {
    return meshstep::lepp(mesh_, tri_.points(), f, [this](HalfEdge h) { return is_segment(h); }, lepp_faces_);
  }

  Point lepp_point(FaceId f) {
    const HalfEdge e = lepp(f);
    const Point &a = point(mesh_.origin(e)), &b = point(mesh_.dest(e));
    const bool boundary = is_segment(e);
    if constexpr (Rec::enabled) hold_lepp_path(e, boundary ? 1 : 2);
    if (boundary || options_.selection == Selection::lepp_midpoint) return {(a.x + b.x) / 2.0, (a.y + b.y) / 2.0};
    // The centroid of the two terminal triangles (a, b, c) and (b, a, d): the mean of their
    // centroids.
    const Point &c = point(mesh_.apex(e)), &d = point(mesh_.apex(mesh_.twin(e)));
    // (c + d) summed first: the same rounding whichever way round the data structure
    // hands over the terminal edge.
    return {(2.0 * (a.x + b.x) + (c.x + d.x)) / 6.0, (2.0 * (a.y + b.y) + (c.y + d.y)) / 6.0};
  }

  // The Lepp path is found while the point is chosen, before the step that inserts it (or
  // splits the segment it encroaches) begins: it is held here and recorded right after that
  // step's step_begin, so that it belongs to its step in the log. Logs written before this
  // have it at the tail of the previous step; the scene still reads them (step_story.cpp).
  struct HeldLepp {
    bool held = false;
    VertexId a = kNone, b = kNone;
    std::uint32_t terminal_triangles = 0;
  };

  void hold_lepp_path(HalfEdge e, std::uint32_t terminal_triangles) {
    lepp_vertices_.clear();
    for (const FaceId g : lepp_faces_) {
      const HalfEdge h = mesh_.half_edge(g);
      lepp_vertices_.insert(lepp_vertices_.end(), {mesh_.origin(h), mesh_.dest(h), mesh_.apex(h)});
    }
    held_lepp_ = {true, mesh_.origin(e), mesh_.dest(e), terminal_triangles};
  }

  // Called right after a step_begin: the held path (if any) opens the step.
  void record_held_lepp_path(Rec& rec) {
    if (!held_lepp_.held) return;
    rec.lepp_path(held_lepp_.a, held_lepp_.b, held_lepp_.terminal_triangles, lepp_vertices_);
    held_lepp_.held = false;
  }

  struct WalkResult {
    enum class Kind { in_face, on_edge, on_vertex, blocked } kind;
    HalfEdge h;  // in_face: an edge of the face; on_edge: the edge; on_vertex: leaving it; blocked: the segment
  };

  // Straight-line walk from the centroid of face f towards p, stopping at the first segment
  // or boundary edge the line crosses. Where the line meets a vertex exactly it starts again
  // from the centroid of the face it reached, so a walk never depends on a tie. Each face is
  // read from its smallest vertex (first_edge): the centroid's rounding and the order the
  // edges are tried in are then the mesh's, not the data structure's.
  WalkResult walk(FaceId f, const Point& p) {
    HalfEdge h = first_edge(f);
    Point from = centroid(h);
    const std::size_t limit = 2 * mesh_.face_count() + 16;
    for (std::size_t step = 0; step < limit; ++step) {
      const HalfEdge e[3] = {h, mesh_.next(h), mesh_.prev(h)};
      double o[3];
      for (int i = 0; i < 3; ++i) o[i] = orient2d(point(mesh_.origin(e[i])), point(mesh_.dest(e[i])), p);
      if (o[0] >= 0.0 && o[1] >= 0.0 && o[2] >= 0.0) {
        for (int i = 0; i < 3; ++i)
          if (p == point(mesh_.origin(e[i]))) return {WalkResult::Kind::on_vertex, e[i]};
        for (int i = 0; i < 3; ++i)
          if (o[i] == 0.0) return {WalkResult::Kind::on_edge, e[i]};
        return {WalkResult::Kind::in_face, h};
      }
      // The exit: an edge p is beyond, with its origin right of the line and its end left.
      int exit = -1;
      bool through_vertex = false;
      for (int i = 0; i < 3 && exit < 0; ++i) {
        if (o[i] >= 0.0) continue;
        const double ou = orient2d(from, p, point(mesh_.origin(e[i])));
        const double ow = orient2d(from, p, point(mesh_.dest(e[i])));
        if (ou <= 0.0 && ow >= 0.0) {
          exit = i;
          through_vertex = ou == 0.0 || ow == 0.0;
        }
      }
      if (exit < 0) {  // numerically off the line (it passed a vertex): any edge p is beyond
        for (int i = 0; i < 3 && exit < 0; ++i)
          if (o[i] < 0.0) exit = i;
        through_vertex = true;
      }
      if (is_segment(e[exit])) return {WalkResult::Kind::blocked, e[exit]};
      h = first_edge(mesh_.face(mesh_.twin(e[exit])));
      if (through_vertex) from = centroid(h);
    }
    throw std::logic_error("refinement: point location did not terminate");
  }

  Point centroid(HalfEdge h) const {
    const Point &a = point(mesh_.origin(h)), &b = point(mesh_.dest(h)), &c = point(mesh_.apex(h));
    return {(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
  }

  // The segments on the boundary of p's cavity (the faces whose circumcircle holds p,
  // reached from the face at `from` without crossing segments) that p encroaches on.
  void encroached_around(HalfEdge from, const Point& p, std::vector<HalfEdge>& out) {
    out.clear();
    cavity_.clear();
    cavity_.push_back(mesh_.face(from));
    for (std::size_t i = 0; i < cavity_.size(); ++i) {
      const HalfEdge first = mesh_.half_edge(cavity_[i]);
      for (const HalfEdge h : {first, mesh_.next(first), mesh_.prev(first)}) {
        if (is_segment(h)) {
          if (encroaches(p, mesh_.origin(h), mesh_.dest(h))) out.push_back(h);
          continue;
        }
        const FaceId g = mesh_.face(mesh_.twin(h));
        if (std::find(cavity_.begin(), cavity_.end(), g) == cavity_.end() && tri_.in_conflict(g, p))
          cavity_.push_back(g);
      }
    }
  }

  void fix(const Candidate& c) {
    held_lepp_.held = false;  // a path held for a point that made no step is not recorded
    fix_with(c, lepp_selection());
  }

  // Lepp under kept segments (--split-segments interior|none). A terminal edge on a segment
  // asks for its midpoint, and a terminal quadrilateral beside one has its centroid inside
  // the segment's diametral circle: both are refused when that segment is kept whole, and
  // on a domain whose Lepp paths all end at its boundary (A.poly) nothing was inserted at
  // all. Rivara's algorithm has no answer (it always splits the terminal edge), so it falls
  // back to what the other point-insertion algorithms insert for that bad triangle: its own
  // off-center (or circumcenter), as Triangle's -Y does, which improves the triangle itself
  // rather than the larger ones at the end of its path. The centroid of a single terminal
  // triangle would not do: on its longest edge, the segment, it lies in the diametral
  // circle unless the triangle is very flat. If the own point is refused too, the triangle
  // is set aside as before, so the run still ends.
  void fix_with(const Candidate& c, bool lepp) {
    Point alternative;
    bool terminal = false;
    const Point p = select(c, alternative, lepp, terminal);
    if (!exact_range_.holds(p)) {  // left as it is, like a triangle at a small input angle
      ++out_of_range_;
      return;
    }
    // Refused for a segment kept whole: a Lepp terminal point falls back (see above).
    const auto refuse = [&] {
      if (terminal) {
        held_lepp_.held = false;  // the step, if any, is the bad triangle's own
        fix_with(c, false);
        return;
      }
      ++kept_refusals_;
    };
    // A Lepp point is located from its terminal triangle: the straight line from the bad
    // triangle to it may cross a segment that the path went around. (The fallback, its own
    // point, from the bad triangle.)
    const WalkResult w = walk(lepp && lepp_selection() ? lepp_faces_.back() : c.face, p);
    if (w.kind == WalkResult::Kind::on_vertex) return;  // a vertex there already: left as it is
    if (w.kind == WalkResult::Kind::blocked || (w.kind == WalkResult::Kind::on_edge && is_segment(w.h))) {
      // Beyond a segment kept whole (outside the domain, for a boundary one) or on it: the
      // triangle is set aside, never retried, so a run with kept segments ends as one without.
      if (!may_split(w.h)) {
        refuse();
        return;
      }
      ++rejected_;
      if (split_segment(w.h, kNone, &p)) requeue(c);
      return;
    }
    encroached_around(w.h, p, encroached_);
    // Encroaching on a segment kept whole: set aside as above (splitting the others it
    // encroaches would not make the point acceptable).
    if (std::any_of(encroached_.begin(), encroached_.end(), [&](HalfEdge e) { return !may_split(e); })) {
      refuse();
      return;
    }
    if (!encroached_.empty()) {
      // One only (the lowest vertex ids): a split moves the other handles, and the triangle comes back with the
      // others still encroached if its point still asks for them.
      ++rejected_;
      const HalfEdge first = *std::min_element(encroached_.begin(), encroached_.end(), [&](HalfEdge x, HalfEdge y) {
        return key(mesh_.origin(x), mesh_.dest(x)) < key(mesh_.origin(y), mesh_.dest(y));
      });
      if (split_segment(first, kNone, &p)) requeue(c);
      return;
    }
    Rec& rec = tri_.recorder();
    rec.step_begin(mesh_, replay::StepKind::refine, c.a, c.b);
    if constexpr (Rec::enabled) {
      // As the algorithm reads: t fails a test, then its Lepp path is followed.
      record_failed_criteria(rec, criteria_, tri_.points(), c.a, c.b, c.c);
      record_held_lepp_path(rec);
      const Point alternatives[1] = {alternative};
      // The fallback beside a kept segment inserts the off-center's point: recorded as
      // such, so that the step's story names the point it inserted. (A terminal point too
      // close to a terminal vertex falls back to the same point and is still recorded as
      // the Lepp selection's, as it always was.)
      const Selection recorded = lepp_selection() && !lepp ? Selection::offcenter : options_.selection;
      rec.point_selected(static_cast<std::uint8_t>(recorded), c.a, c.b, c.c, p,
                         std::span<const Point>(alternatives, p == alternative ? 0 : 1));
    }
    const VertexId v = tri_.add_point(p);
    grow_huge(on_segment_);
    on_segment_.push_back({kNone, kNone});
    const HalfEdge out = tri_.insert_in_step(v, w.h);
    ++triangles_split_;
    after_insertion(out);
    // A Lepp point may land away from the bad triangle: it stays queued until it is gone.
    if (lepp_selection()) requeue(c);
  }

  void requeue(Candidate c) {
    if (still_there(c)) push_bad(priority(quality::shape(point(c.a), point(c.b), point(c.c))), c);
  }

  // Splits the segment of h: at its midpoint, or on a concentric shell (split_point).
  // `by`: the vertex or rejected point that encroached, for the record.
  // Returns false, changing nothing, when the rounded split point would not leave both
  // halves with valid triangles (a subsegment a few ulps long): the floor of refinement.
  bool split_segment(HalfEdge h, VertexId by_vertex, const Point* by_point) {
    const VertexId a = mesh_.origin(h), b = mesh_.dest(h);
    // Does another segment meet a-b at a (at b) in a triangle beside it?
    bool corner_a = is_segment(mesh_.prev(h)), corner_b = is_segment(mesh_.next(h));
    if (const HalfEdge t = mesh_.twin(h); t != kNone) {
      corner_a = corner_a || is_segment(mesh_.next(t));
      corner_b = corner_b || is_segment(mesh_.prev(t));
    }
    const Point p = detail::inside_boundary(mesh_, tri_.points(), h, split_point(a, b, corner_a, corner_b));
    if (!splits_cleanly(h, p) || !exact_range_.holds(p)) {
      ++unsplittable_;
      return false;
    }
    Rec& rec = tri_.recorder();
    rec.step_begin(mesh_, replay::StepKind::split_segment, a, b);
    if constexpr (Rec::enabled) {
      record_held_lepp_path(rec);  // the path whose point encroached, when a Lepp point did
      const Point encroacher = by_point ? *by_point : (by_vertex != kNone ? point(by_vertex) : point(mesh_.apex(h)));
      rec.encroached(a, b, by_point ? kNone : (by_vertex != kNone ? by_vertex : mesh_.apex(h)), encroacher);
    }
    const SubsegmentInfo info = take_subsegment(a, b);
    HalfEdge out = tri_.insert_on_edge(p, h, replay::SplitReason::encroached);
    const VertexId v = mesh_.origin(out);
    // p is rounded, a hair off the segment's line: the edges from it are not Delaunay by
    // construction as they would be for a point exactly on the line, so check them too.
    stack_.clear();
    tri_.for_each_out_edge(out, [&](HalfEdge e) {
      stack_.push_back(e);
      stack_.push_back(mesh_.next(e));
    });
    flipped_.clear();
    tri_.make_delaunay(stack_, &flipped_);
    // A flip here may make a face without v (v lies a hair off the line, beyond an old
    // edge), often one the split destroyed: remembered for still_there(), and checked here,
    // since after_insertion() checks only the faces round v.
    away_from_v_.clear();
    for (const FaceId f : flipped_)
      if (const HalfEdge e = mesh_.half_edge(f); mesh_.is_live(f) && mesh_.origin(e) != v && mesh_.dest(e) != v &&
                                                 mesh_.apex(e) != v) {
        recreated_.insert(triangle_hash(face_key(f)));
        away_from_v_.push_back(f);
      }
    std::sort(away_from_v_.begin(), away_from_v_.end());
    away_from_v_.erase(std::unique(away_from_v_.begin(), away_from_v_.end()), away_from_v_.end());
    check_faces(away_from_v_);
    out = mesh_.vertex_half_edge(v);
    grow_huge(on_segment_);
    on_segment_.push_back({info.a, info.b});
    subsegments_[key(a, v)] = info;
    subsegments_[key(v, b)] = info;
    ++segment_splits_;
    segments_.push_back({std::min(a, b), v, kNone});
    segments_.push_back({v, std::max(a, b), kNone});
    // Not at a corner (Chew's rule, as Triangle): there the free vertices are what the
    // shells and the triangles between the two segments are made of.
    if (deletes_free_vertices() && !corner_a && !corner_b) {
      delete_free_apexes(a, b, v);
      out = mesh_.vertex_half_edge(v);
    }
    after_insertion(out);
    return true;
  }

  bool deletes_free_vertices() const {
    switch (options_.delete_free) {
      case FreeVertexDeletion::always: return true;
      case FreeVertexDeletion::never: return false;
      case FreeVertexDeletion::unless_sized: break;
    }
    return !criteria_.sized();
  }

  // After subsegment a-b is split at v away from corners: while a triangle on either side
  // of a-v or v-b has for its apex a free Steiner vertex (not on a segment) strictly inside
  // a-b's diametral circle, that vertex is removed, and the apex that takes its place is
  // looked at in turn (Chew's rule, after Triangle, which does it on a-b before the split).
  // Only the vertices facing the segment go: removing every free vertex in the circle made
  // 71k removals on A.poly under an area bound of 1e-7, against 34k, for nothing. The edges
  // are found from v, whose triangles make one fan (a vertex where holes touch may have
  // several, and edges from it can be out of reach). The triangles each removal makes are
  // checked, and remembered for still_there() (a removal may bring back triangles the
  // vertex's insertion destroyed).
  void delete_free_apexes(VertexId a, VertexId b, VertexId v) {
    // The half-edge on one side of v-end: v -> end, or end -> v.
    const auto side_of = [&](VertexId end, bool towards_v) {
      if (!towards_v) return tri_.first_out_edge(mesh_.vertex_half_edge(v), [&](HalfEdge h) { return mesh_.dest(h) == end; });
      const HalfEdge h =
          tri_.first_out_edge(mesh_.vertex_half_edge(v), [&](HalfEdge g) { return mesh_.origin(mesh_.prev(g)) == end; });
      return h == kNone ? kNone : mesh_.prev(h);
    };
    for (const VertexId end : {a, b}) {
      for (const bool towards_v : {false, true}) {
        for (;;) {
          const HalfEdge e = side_of(end, towards_v);
          if (e == kNone) break;
          const VertexId x = mesh_.apex(e);
          if (x < input_count_ || on_segment_[x].first != kNone || !in_diametral_circle(point(x), a, b)) break;
          const HalfEdge out = mesh_.vertex_half_edge(x);
          if (out == kNone || !remover_.plan(out)) break;
          made_.assign(remover_.new_triangles().begin(), remover_.new_triangles().end());
          remover_.apply();
          ++removed_;
          for (const auto& t : made_) {
            std::array<VertexId, 3> k = t;
            std::sort(k.begin(), k.end());
            recreated_.insert(triangle_hash(k));
            if (const HalfEdge f = tri_.find_edge(t[0], t[1]); f != kNone && mesh_.apex(f) == t[2]) check_face(mesh_.face(f));
          }
        }
      }
    }
  }

  bool splits_cleanly(HalfEdge h, const Point& p) const { return detail::splits_cleanly(mesh_, tri_.points(), h, p); }

  SubsegmentInfo take_subsegment(VertexId a, VertexId b) {
    const auto it = subsegments_.find(key(a, b));
    if (it == subsegments_.end()) return {1, a, b};
    const SubsegmentInfo info = it->second;
    subsegments_.erase(it);
    return info;
  }

  // Where to split subsegment a-b, given whether another segment meets it at either end in
  // a triangle beside it: there, on a concentric shell round that end (the power of two
  // nearest half the length, so the pieces are at worst 1:2), else at the midpoint. With a
  // corner at both ends, round the one with the smaller id: the same whichever way the data
  // structure hands the edge over.
  Point split_point(VertexId a, VertexId b, bool corner_a, bool corner_b) const {
    const Point &pa = point(a), &pb = point(b);
    if (!corner_a && !corner_b) return {(pa.x + pb.x) / 2.0, (pa.y + pb.y) / 2.0};
    const bool from_a = corner_a && (!corner_b || a < b);
    const Point &from = from_a ? pa : pb, &to = from_a ? pb : pa;
    const double length = std::sqrt(quality::squared_distance(pa, pb));
    const double d = std::exp2(std::round(std::log2(length / 2.0)));
    const double t = d / length;
    return {from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t};
  }

  // After a vertex went in: check the faces around it, and the segments across from it.
  void after_insertion(HalfEdge out) {
    const VertexId v = mesh_.origin(out);
    HalfEdge h = star_start(out);
    for (;;) {  // counterclockwise around v
      const HalfEdge far = mesh_.next(h);
      if (is_segment(far) && encroaches(point(v), mesh_.origin(far), mesh_.dest(far)))
        segments_.push_back({mesh_.origin(far), mesh_.dest(far), far});
      check_face(mesh_.face(h));
      const HalfEdge t = mesh_.twin(mesh_.prev(h));
      if (t == kNone || t == star_start_) break;
      h = t;
    }
  }

  // Where to start going counterclockwise around origin(out) so that the order is the
  // mesh's own, not the data structure's: the clockwise-most edge on a boundary, else the
  // edge to the smallest vertex id. (Faces are queued in the order they are checked.)
  HalfEdge star_start(HalfEdge out) {
    HalfEdge start = out;
    for (HalfEdge h = out;;) {
      const HalfEdge t = mesh_.twin(h);
      if (t == kNone) {
        start = h;
        break;
      }
      h = mesh_.next(t);  // the next edge clockwise
      if (h == out) break;
      if (mesh_.dest(h) < mesh_.dest(start)) start = h;
    }
    star_start_ = start;
    return start;
  }

  // Input vertices where two segments meet at less than 60 degrees: refinement cannot make
  // the triangles there meet the bounds, and the report says so.
  void find_small_input_angles(const std::vector<Segment>& boundary) {
    std::unordered_map<VertexId, std::vector<VertexId>> around;
    for (const Segment& s : boundary) {
      around[s.a].push_back(s.b);
      around[s.b].push_back(s.a);
    }
    small_angle_.assign(tri_.points().size(), 0);
    for (const auto& [v, ends] : around)
      for (std::size_t i = 0; i < ends.size(); ++i)
        for (std::size_t j = i + 1; j < ends.size(); ++j) {
          const Point &o = point(v), &p = point(ends[i]), &q = point(ends[j]);
          const double ux = p.x - o.x, uy = p.y - o.y, wx = q.x - o.x, wy = q.y - o.y;
          const double cos_angle = (ux * wx + uy * wy) / std::sqrt((ux * ux + uy * uy) * (wx * wx + wy * wy));
          if (cos_angle > 0.5) small_angle_[v] = 1;
        }
  }

  // Near a small input angle: at such a vertex, or a Steiner vertex on a segment, since the
  // shells around it are where the bound gives way.
  bool near_small_angle(VertexId v) const {
    if (v < small_angle_.size() && small_angle_[v]) return true;
    const auto& seg = on_segment_[v];
    return seg.first != kNone && (small_angle_[seg.first] || small_angle_[seg.second]);
  }

  void assess(RefineReport& report) {
    std::size_t below = 0, bad = 0, explained = 0, skipped = 0, in_region_count = 0;
    for (FaceId f = 0; f < mesh_.face_capacity(); ++f) {
      if (!mesh_.is_live(f)) continue;
      const HalfEdge h = first_edge(f);
      const VertexId a = mesh_.origin(h), b = mesh_.dest(h), c = mesh_.apex(h);
      if (!in_region(criteria_, point(a), point(b), point(c))) continue;  // the report speaks of the region
      ++in_region_count;
      const quality::Shape s = quality::shape(point(a), point(b), point(c));
      const bool below_angle = s.sin2_min_angle() < criteria_.sin2_min_angle;
      const bool fails = angle_bad(s) || too_large(criteria_, s, point(a), point(b), point(c));
      below += below_angle;
      if (!fails) continue;
      ++bad;
      if (near_small_angle(a) || near_small_angle(b) || near_small_angle(c)) ++explained;
      skipped += cannot_improve(h, s);
    }
    report.region_triangles = in_region_count;
    report.skipped_small_angle = skipped;
    report.below_min_angle = below;
    report.bad_triangles = bad;
    report.bad_near_small_input_angle = explained;
    report.bounds_met = bad == 0;
  }

  Triangulation<Mesh, Rec>& tri_;
  Mesh& mesh_;
  std::size_t input_count_;
  ScaledCriteria criteria_;
  const RefineOptions& options_;
  std::unordered_map<std::uint64_t, SubsegmentInfo> subsegments_;  // and boundary edges
  // By vertex: the ends of the segment a split put it on ({kNone, kNone}: not on one).
  std::vector<std::pair<VertexId, VertexId>> on_segment_;
  std::vector<std::uint8_t> small_angle_;           // by vertex: two segments meet at < 60 degrees
  std::vector<Suspect> segments_;  // subsegments to check for encroachment
  // Bad triangles by priority (bucket_of), the first bucket first.
  static constexpr std::size_t kBuckets = 4196;  // enough for either order (bucket_of)
  std::vector<HugeArray<Candidate>> buckets_ = std::vector<HugeArray<Candidate>>(kBuckets);
  std::size_t lowest_ = kBuckets;
  std::deque<Candidate> fifo_;
  std::vector<FaceId> star_;
  std::vector<FaceId> lepp_faces_;
  std::vector<VertexId> lepp_vertices_;
  HeldLepp held_lepp_;
  HalfEdge star_start_ = kNone;
  std::vector<FaceId> cavity_;
  std::vector<HalfEdge> stack_;
  std::vector<HalfEdge> encroached_;
  std::vector<FaceId> flipped_;
  std::vector<FaceId> away_from_v_;  // faces a split's flips made without the new vertex
  std::vector<std::array<VertexId, 3>> made_;  // the triangles a removal near a split makes
  VertexRemover<Mesh, Rec> remover_{tri_};
  std::unordered_set<std::uint64_t> recreated_;  // hashes of triangles a split's flips made (collisions: a search more)
  std::size_t segment_splits_ = 0, triangles_split_ = 0, rejected_ = 0, unsplittable_ = 0, removed_ = 0;
  std::size_t out_of_range_ = 0;  // points refused for coordinates below the exact range
  std::size_t kept_refusals_ = 0;  // bad triangles set aside for a segment kept whole
  ExactRange exact_range_;
};

}  // namespace meshstep::detail

