// Recording as a policy of the algorithms.
//
// Algorithms are templates over a recorder type and route every mesh mutation through it:
// `rec.flip(mesh, h, reason)` instead of `mesh.flip(h)`. NullRecorder performs the mutation
// and nothing else, and its notification hooks are empty inline functions, so a run with
// recording off compiles to the same code as before recording existed. Recorder performs
// the mutation, then appends the event with the faces it wrote to an EventSink.
//
// Both expose the same members; the concept RecordingPolicy names them.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <span>
#include <vector>

#include "meshstep/mesh/concept.hpp"
#include "meshstep/replay/event.hpp"
#include "meshstep/replay/event_sink.hpp"

namespace meshstep::replay {

// The record of face slot f as the data structure holds it (dead if f is not live).
// Inlined always: the recorder reads a handful per change, in the algorithm's hot loop.
template <TriangleMesh Mesh>
[[gnu::always_inline]] inline FaceRecord face_record(const Mesh& m, FaceId f) {
  FaceRecord r;
  if (!m.is_live(f)) return r;
  const HalfEdge h = m.half_edge(f), n = m.next(h);
  r.v = {m.origin(h), m.origin(n), m.origin(m.next(n))};
  r.constrained = static_cast<std::uint8_t>(m.constraint_mask(f));
  return r;
}

// Every face slot of the mesh, dead ones included: what a replay must reproduce.
template <TriangleMesh Mesh>
std::vector<FaceRecord> face_records(const Mesh& m) {
  std::vector<FaceRecord> out(m.face_capacity());
  for (FaceId f = 0; f < out.size(); ++f) out[f] = face_record(m, f);
  return out;
}

// The faces a point location walked through, for its locate event: the walk notes each face
// it enters with the vertices it read there anyway, put in the order the data structure
// lists them, into a ring of the last kMaxFaces (a few stores per face however long the
// walk). The triangulation keeps one only when recording (NoWalkTrace otherwise).
class WalkTrace {
 public:
  // A longer walk (a bad hint, a pathological input) keeps its last 512 faces: where it
  // arrived is what a picture shows, and a log must not grow with the walk.
  static constexpr std::uint32_t kMaxFaces = 512;

  void start() { visited_ = 0; }
  // The walk entered the face of half-edge h, whose vertices from h on are a, b, c; corner:
  // where h stands in its face (TriangleMesh::corner).
  void enter(std::uint32_t corner, VertexId a, VertexId b, VertexId c) {
    VertexId* v = &ring_[3 * (visited_++ % kMaxFaces)];
    v[corner] = a;
    v[corner == 2 ? 0 : corner + 1] = b;
    v[corner == 0 ? 2 : corner - 1] = c;
  }
  std::uint32_t visited() const { return visited_; }
  std::uint32_t kept() const { return std::min(visited_, kMaxFaces); }
  // The vertices of the faces kept, three each, in the order the walk entered them: the
  // first span, then the second (empty unless the ring wrapped).
  std::array<std::span<const VertexId>, 2> kept_faces() const {
    const std::size_t oldest = visited_ > kMaxFaces ? 3 * (visited_ % kMaxFaces) : 0;
    const std::span<const VertexId> ring(ring_.data(), 3 * kept());
    return {ring.subspan(oldest), ring.first(oldest)};
  }

 private:
  std::array<VertexId, 3 * kMaxFaces> ring_;
  std::uint32_t visited_ = 0;
};
struct NoWalkTrace {};

struct NullRecorder {
  static constexpr bool enabled = false;

  template <TriangleMesh M> HalfEdge init_sphere(M& m, VertexId a, VertexId b, VertexId c) {
    return m.init_sphere(a, b, c, kInfiniteVertex);
  }
  template <TriangleMesh M> HalfEdge flip(M& m, HalfEdge h, FlipReason) { return m.flip(h); }
  template <TriangleMesh M> HalfEdge split_face(M& m, FaceId f, VertexId v) {
    return m.split_face(f, v);
  }
  template <TriangleMesh M> HalfEdge split_edge(M& m, HalfEdge h, VertexId v, SplitReason) {
    return m.split_edge(h, v);
  }
  template <TriangleMesh M>
  HalfEdge star_cavity(M& m, std::span<const HalfEdge> ring, std::span<const FaceId> faces,
                       VertexId v) {
    return m.star_cavity(ring, faces, v);
  }
  template <TriangleMesh M> HalfEdge merge_star(M& m, HalfEdge h) { return m.merge_star(h); }
  template <TriangleMesh M> void remove_face(M& m, FaceId f, RemoveReason) { m.remove_face(f); }
  template <TriangleMesh M> void set_constrained(M& m, HalfEdge h, bool on, int) {
    m.set_constrained(h, on);
  }

  template <TriangleMesh M> void step_begin(const M&, StepKind, VertexId = kNone, VertexId = kNone) {}
  template <TriangleMesh M> void run_end(const M&) {}
  void phase_begin(Phase) {}
  void phase_end(Phase) {}
  void vertex(VertexId, const Point&) {}
  void duplicate(VertexId, VertexId, const Point&) {}
  void locate(VertexId, const WalkTrace&, FaceId, LocateResult) {}
  void criterion_test(Criterion, bool, VertexId, VertexId, VertexId, double) {}
  void point_selected(std::uint8_t, VertexId, VertexId, VertexId, const Point&, std::span<const Point>) {}
  void encroached(VertexId, VertexId, VertexId, const Point&) {}
  void lepp_path(VertexId, VertexId, std::uint32_t, std::span<const VertexId>) {}
  void elevation(VertexId, double) {}
};

class Recorder {
 public:
  static constexpr bool enabled = true;

  explicit Recorder(EventSink& sink) : sink_(&sink) {}

  // How the algorithm's vertices map to the input: vertex v < input_of.size() is input
  // vertex input_of[v], later ones are Steiner vertices; coordinates are stored scaled by
  // 2^-exponent (undoing the triangulator's exact power-of-two scaling).
  void set_vertex_context(std::span<const std::uint32_t> input_of, int exponent) {
    input_of_ = input_of;
    exponent_ = exponent;
  }
  // Tests: called with every face slot at each step boundary and at the end of the run.
  void observe_steps(std::function<void(const std::vector<FaceRecord>&)> observer) {
    observer_ = std::move(observer);
  }

  // Mutations ------------------------------------------------------------------------------
  // Each writes the faces the change replaces (read before it, while they are in cache),
  // performs it, then writes the faces it made.
  template <TriangleMesh M> HalfEdge init_sphere(M& m, VertexId a, VertexId b, VertexId c) {
    begin(EventType::init, 0);
    ids(a, b, c);
    sink_->put(0u);  // replaces nothing
    const HalfEdge h = m.init_sphere(a, b, c, kInfiniteVertex);
    const std::size_t count = sink_->placeholder();
    std::uint32_t n = 0;
    for (FaceId f = 0; f < m.face_capacity(); ++f)
      if (m.is_live(f)) {
        put_face(m, f);
        ++n;
      }
    sink_->fill(count, n);
    end_event();
    return h;
  }

  // Flips are most of a run's events: packed (see event_sink.hpp) rather than as records.
  template <TriangleMesh M> HalfEdge flip(M& m, HalfEdge h, FlipReason reason) {
    const HalfEdge t = m.twin(h);
    const VertexId a = m.origin(h), b = m.dest(h), c = m.apex(h), d = m.apex(t);
    const FaceId f = m.face(h), g = m.face(t);
    std::uint32_t packed = face_bits(m, h) | face_bits(m, t) << 5;
    const HalfEdge e = m.flip(h), et = m.twin(e);
    const FaceId f2 = m.face(e), g2 = m.face(et);
    packed |= face_bits(m, e) << 10 | face_bits(m, et) << 15;
    std::uint32_t* out = sink_->extend(10);
    out[0] = kFlipWord | std::uint32_t{static_cast<std::uint8_t>(reason)} << 8;
    out[1] = a;
    out[2] = b;
    out[3] = c;
    out[4] = d;
    out[5] = f;
    out[6] = g;
    out[7] = f2;
    out[8] = g2;
    out[9] = packed;
    end_event();
    return e;
  }

  // One per inserted vertex: packed as well (see event_sink.hpp).
  template <TriangleMesh M> HalfEdge split_face(M& m, FaceId f, VertexId v) {
    const FaceRecord old = face_record(m, f);
    const HalfEdge out = m.split_face(f, v);
    std::uint32_t* w = sink_->extend(10);
    w[0] = kSplitFaceWord;
    w[1] = v;
    w[2] = old.v[0];
    w[3] = old.v[1];
    w[4] = old.v[2];
    w[5] = f;
    std::uint32_t packed = old.constrained;
    // The star of v: three faces, closed. `out` leaves v toward old.v[0] (the concept's
    // split_face), so going round, the i-th face holds the old face's edge i; and h leaves
    // v, so v stands at corner(h) of its face. Both are read from positions, never by
    // looking ids up: a face may name one id twice (a surface's seam, surface_loader.hpp).
    HalfEdge h = out;
    for (std::uint32_t i = 0; i < 3; ++i, h = m.twin(m.prev(h))) {
      const FaceId s = m.face(h);
      w[6 + i] = s;
      packed |= spoke_face_bits(i, m.corner(h), face_record(m, s).constrained) << (3 + 7 * i);
    }
    w[9] = packed;
    end_event();
    return out;
  }

  template <TriangleMesh M>
  HalfEdge split_edge(M& m, HalfEdge h, VertexId v, SplitReason reason) {
    const HalfEdge t = m.twin(h);
    begin(EventType::split_edge, static_cast<std::uint8_t>(reason));
    ids(v, m.origin(h), m.dest(h));
    put_edge_faces(m, h, t);
    const HalfEdge out = m.split_edge(h, v);
    put_star(m, out);
    end_event();
    return out;
  }

  template <TriangleMesh M>
  HalfEdge star_cavity(M& m, std::span<const HalfEdge> ring, std::span<const FaceId> faces,
                       VertexId v) {
    begin(EventType::cavity, 0);
    ids(v);
    sink_->put(static_cast<std::uint32_t>(faces.size()));
    for (const FaceId f : faces) put_face(m, f);
    const HalfEdge out = m.star_cavity(ring, faces, v);
    put_star(m, out);
    end_event();
    return out;
  }

  // The last move of a vertex removal (flips bring the vertex to degree 3 first).
  template <TriangleMesh M> HalfEdge merge_star(M& m, HalfEdge h) {
    begin(EventType::remove_vertex, 0);
    ids(m.origin(h));
    const HalfEdge h1 = m.twin(m.prev(h)), h2 = m.twin(m.prev(h1));
    put_faces(m, {m.face(h), m.face(h1), m.face(h2)});
    const HalfEdge out = m.merge_star(h);
    put_faces(m, {m.face(out)});
    end_event();
    return out;
  }

  template <TriangleMesh M> void remove_face(M& m, FaceId f, RemoveReason reason) {
    begin(EventType::remove_face, static_cast<std::uint8_t>(reason));
    put_faces(m, {f});
    m.remove_face(f);
    sink_->put(0u);  // makes nothing
    end_event();
  }

  template <TriangleMesh M> void set_constrained(M& m, HalfEdge h, bool on, int marker) {
    const HalfEdge t = m.twin(h);
    begin(EventType::constrain, on ? 1 : 0);
    ids(m.origin(h), m.dest(h), static_cast<std::uint32_t>(marker));
    put_edge_faces(m, h, t);
    m.set_constrained(h, on);
    put_edge_faces(m, h, t);
    end_event();
  }

  // Notifications --------------------------------------------------------------------------
  template <TriangleMesh M>
  void step_begin(const M& m, StepKind kind, VertexId s0 = kNone, VertexId s1 = kNone) {
    if (observer_) observer_(face_records(m));
    const KeyframePolicy& policy = sink_->keyframe_policy();
    if (since_keyframe_ >= policy.min_events &&
        static_cast<double>(since_keyframe_) >= policy.factor * static_cast<double>(m.face_count()))
      keyframe(m);
    event(EventType::step_begin, static_cast<std::uint8_t>(kind), s0, s1);
  }
  // The end of the run: a last keyframe, read from the data structure, is what a replay
  // of all the events must reproduce.
  template <TriangleMesh M> void run_end(const M& m) {
    if (observer_) observer_(face_records(m));
    keyframe(m);
  }
  void phase_begin(Phase phase) { event(EventType::phase_begin, static_cast<std::uint8_t>(phase)); }
  void phase_end(Phase phase) { event(EventType::phase_end, static_cast<std::uint8_t>(phase)); }

  void vertex(VertexId v, const Point& p) {
    event_with_point(EventType::vertex, p, v, input_index(v));
  }
  void duplicate(VertexId v, VertexId same_as, const Point& p) {
    event_with_point(EventType::duplicate, p, v, same_as, input_index(v));
  }
  // Vertex v was located in slot `found` by `walk`. Its list: the faces the walk kept, three
  // vertex ids each as the data structure lists them, the last one the record of `found`.
  void locate(VertexId v, const WalkTrace& walk, FaceId found, LocateResult result) {
    std::uint32_t* w = sink_->extend(5 + 3 * walk.kept());
    *w++ = static_cast<std::uint32_t>(EventType::locate) | std::uint32_t{static_cast<std::uint8_t>(result)} << 8;
    *w++ = v;
    *w++ = walk.visited();
    *w++ = found;
    *w++ = 3 * walk.kept();
    for (const std::span<const VertexId> run : walk.kept_faces()) w = std::copy(run.begin(), run.end(), w);
    end_event();
  }
  // Refinement: the triangle (a, b, c) met the criterion's bound or not, by the measure
  // `value` (in the triangulation's scaled coordinates: stored unscaled, like points).
  void criterion_test(Criterion criterion, bool passed, VertexId a, VertexId b, VertexId c, double value) {
    const auto code = static_cast<std::uint8_t>(static_cast<std::uint8_t>(criterion) | (passed ? kCriterionPassed : 0));
    begin(EventType::criterion_test, code);
    ids(a, b, c);
    sink_->put(std::ldexp(value, -length_power(criterion) * exponent_));
    end_event();
  }
  // Refinement: the point chosen for the bad triangle (a, b, c) by a strategy, with the
  // other candidates it weighed (a circumcenter beside an off-center, say).
  void point_selected(std::uint8_t strategy, VertexId a, VertexId b, VertexId c, const Point& chosen,
                      std::span<const Point> alternatives) {
    begin(EventType::point_selected, strategy);
    ids(a, b, c);
    put_point(chosen);
    sink_->put(0u);  // no list
    sink_->put(static_cast<std::uint32_t>(alternatives.size()));
    for (const Point& p : alternatives) put_point(p);
    end_event();
  }
  // A longest-edge propagation path: its terminal edge a-b, how many terminal triangles
  // (1 on the boundary, else 2), and the path's triangles, three vertex ids each.
  void lepp_path(VertexId a, VertexId b, std::uint32_t terminal_triangles, std::span<const VertexId> triangles) {
    begin(EventType::lepp_path, 0);
    ids(a, b, terminal_triangles);
    sink_->put(static_cast<std::uint32_t>(triangles.size()));
    for (const VertexId v : triangles) sink_->put(v);
    end_event();
  }
  // Terrains: vertex v stands at height z (after its vertex event; heights are not scaled).
  void elevation(VertexId v, double z) {
    begin(EventType::elevation, 0);
    ids(v);
    sink_->put(z);
    end_event();
  }
  // Segment a-b is encroached by vertex v (kNone: by a point not inserted, p).
  void encroached(VertexId a, VertexId b, VertexId v, const Point& p) {
    event_with_point(EventType::encroached, p, a, b, v);
  }

 private:
  void begin(EventType type, std::uint8_t code) {
    sink_->put(static_cast<std::uint32_t>(type) | (std::uint32_t{code} << 8));
  }
  // A whole event of ids only (and a point): one append, the words written in place.
  template <class... Ids> void event(EventType type, std::uint8_t code, Ids... values) {
    std::uint32_t* w = sink_->extend(1 + sizeof...(Ids));
    *w++ = static_cast<std::uint32_t>(type) | (std::uint32_t{code} << 8);
    ((*w++ = static_cast<std::uint32_t>(values)), ...);
    end_event();
  }
  template <class... Ids> void event_with_point(EventType type, const Point& p, Ids... values) {
    std::uint32_t* w = sink_->extend(1 + sizeof...(Ids) + 4);
    *w++ = static_cast<std::uint32_t>(type);
    ((*w++ = static_cast<std::uint32_t>(values)), ...);
    const Point q = exponent_ == 0 ? p : Point{std::ldexp(p.x, -exponent_), std::ldexp(p.y, -exponent_)};
    for (const double d : {q.x, q.y}) {
      const auto bits = std::bit_cast<std::uint64_t>(d);
      *w++ = static_cast<std::uint32_t>(bits);
      *w++ = static_cast<std::uint32_t>(bits >> 32);
    }
    end_event();
  }
  void end_event() {
    ++since_keyframe_;
    sink_->end_event();
  }
  // A copy of every face slot, at a step boundary.
  template <TriangleMesh M> void keyframe(const M& m) {
    sink_->put(kKeyframeWord);
    sink_->put(static_cast<std::uint32_t>(m.face_capacity()));
    std::uint32_t* out = sink_->extend(4 * m.face_capacity());  // millions of faces: no push_back
    for (FaceId f = 0; f < m.face_capacity(); ++f, out += 4) {
      const FaceRecord r = face_record(m, f);
      out[0] = r.v[0];
      out[1] = r.v[1];
      out[2] = r.v[2];
      out[3] = r.constrained;
    }
    sink_->end_event();
    since_keyframe_ = 0;
  }
  // For the face of h = u->v: its rotation (which of u, v and the third vertex the data
  // structure lists first: 0, 2 or 1 when h is its first, second or third half-edge) and
  // its constraint bits, packed in 5 bits. From half-edge handles alone, without reading
  // the face's vertices: a flip asks for four of these.
  template <TriangleMesh M> static std::uint32_t face_bits(const M& m, HalfEdge h) {
    const std::uint32_t corner = m.corner(h);
    const std::uint32_t rotation = corner == 0 ? 0 : 3 - corner;
    return rotation | m.constraint_mask(m.face(h)) << 2;
  }
  // A face (x, y, v) made by splitting a face at v, x -> y the old face's edge `edge`, v at
  // corner k of the data structure's listing: which edge (2 bits), the rotation the data
  // structure lists it in (2 bits), constraint bits (3).
  static std::uint32_t spoke_face_bits(std::uint32_t edge, std::uint32_t k, std::uint8_t constrained) {
    return edge | (2 - k) << 2 | std::uint32_t{constrained} << 4;
  }
  // The faces on both sides of the edge of h (t: its twin, kNone on the boundary).
  template <TriangleMesh M> void put_edge_faces(const M& m, HalfEdge h, HalfEdge t) {
    if (t == kNone) put_faces(m, {m.face(h)});
    else put_faces(m, {m.face(h), m.face(t)});
  }
  template <TriangleMesh M> void put_faces(const M& m, std::initializer_list<FaceId> faces) {
    sink_->put(static_cast<std::uint32_t>(faces.size()));
    for (const FaceId f : faces) put_face(m, f);
  }
  void put_point(const Point& p) {
    sink_->put(exponent_ == 0 ? p : Point{std::ldexp(p.x, -exponent_), std::ldexp(p.y, -exponent_)});
  }
  template <class... Ids> void ids(Ids... values) { (sink_->put(static_cast<std::uint32_t>(values)), ...); }
  std::uint32_t input_index(VertexId v) const {
    return v < input_of_.size() ? input_of_[v] : v;
  }
  template <TriangleMesh M> void put_face(const M& m, FaceId f) {
    const FaceRecord r = face_record(m, f);
    sink_->put(f);
    sink_->put(r.v[0]);
    sink_->put(r.v[1]);
    sink_->put(r.v[2]);
    sink_->put(std::uint32_t{r.constrained});
  }
  // Writes the count and the records of the faces around the origin of `out` (both ways
  // round on a boundary).
  template <TriangleMesh M> void put_star(const M& m, HalfEdge out) {
    const std::size_t count = sink_->placeholder();
    std::uint32_t n = 0;
    HalfEdge h = out;
    do {
      put_face(m, m.face(h));
      ++n;
      h = m.twin(m.prev(h));
    } while (h != kNone && h != out);
    if (h == kNone) {
      for (HalfEdge g = m.twin(out); g != kNone; g = m.twin(g)) {
        g = m.next(g);
        put_face(m, m.face(g));
        ++n;
      }
    }
    sink_->fill(count, n);
  }

  EventSink* sink_;
  std::span<const std::uint32_t> input_of_;
  int exponent_ = 0;
  std::function<void(const std::vector<FaceRecord>&)> observer_;
  std::uint64_t since_keyframe_ = 0;  // events since the last keyframe
};

template <class R>
concept RecordingPolicy = requires { { R::enabled } -> std::convertible_to<bool>; };

}  // namespace meshstep::replay
