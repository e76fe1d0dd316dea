// Triangle-based data structure: per face three vertices and three neighbours.
//
// Face f owns the half-edges 3f, 3f+1, 3f+2; half-edge 3f+i runs from vertex i to vertex
// i+1 (mod 3) of f, so next/prev/face/apex are arithmetic and need no storage. The
// neighbour slot of a half-edge holds its twin half-edge (neighbour face and the index of
// the shared edge in it, as Triangle's oriented triangles do), which makes twin() one load;
// the top bit of that slot is the edge's constraint flag. 24 bytes per face in all.
#pragma once

#include <array>
#include <cassert>
#include <cstdint>
#include <span>
#include <vector>

#include "meshstep/huge_array.hpp"
#include "meshstep/mesh/handles.hpp"
#include "meshstep/release.hpp"

namespace meshstep {

class Tds {
 public:
  static constexpr const char* kName = "tds";

  // Navigation ----------------------------------------------------------------------------
  VertexId origin(HalfEdge h) const { return vertices_[h]; }
  VertexId dest(HalfEdge h) const { return vertices_[next(h)]; }
  VertexId apex(HalfEdge h) const { return vertices_[prev(h)]; }
  HalfEdge next(HalfEdge h) const { return h % 3 == 2 ? h - 2 : h + 1; }
  HalfEdge prev(HalfEdge h) const { return h % 3 == 0 ? h + 2 : h - 1; }
  HalfEdge twin(HalfEdge h) const {
    const std::uint32_t t = twins_[h] & kTwinMask;
    return t == kTwinMask ? kNone : t;
  }
  FaceId face(HalfEdge h) const { return h / 3; }
  HalfEdge half_edge(FaceId f) const { return 3 * f; }
  HalfEdge vertex_half_edge(VertexId v) const {
    return v == kInfiniteVertex ? infinite_half_edge_ : vertex_half_edges_[v];
  }
  bool is_constrained(HalfEdge h) const { return (twins_[h] & kConstrainedBit) != 0; }
  std::uint32_t corner(HalfEdge h) const { return h % 3; }
  std::uint32_t constraint_mask(FaceId f) const {
    const std::uint32_t* t = &twins_[3 * f];
    return std::uint32_t{(t[0] & kConstrainedBit) != 0} | std::uint32_t{(t[1] & kConstrainedBit) != 0} << 1 |
           std::uint32_t{(t[2] & kConstrainedBit) != 0} << 2;
  }

  // Size ----------------------------------------------------------------------------------
  std::size_t face_capacity() const { return vertices_.size() / 3; }
  std::size_t face_count() const { return face_capacity() - free_faces_.size(); }
  bool is_live(FaceId f) const { return vertices_[3 * f] != kNone; }
  std::size_t memory_bytes() const {
    return vertices_.capacity() * sizeof(VertexId) + twins_.capacity() * sizeof(std::uint32_t) +
           vertex_half_edges_.capacity() * sizeof(HalfEdge) +
           free_faces_.capacity() * sizeof(FaceId);
  }

  // Construction and mutation ---------------------------------------------------------------
  void reserve(std::size_t vertices, std::size_t faces) {
    vertex_half_edges_.reserve(vertices);
    vertices_.reserve(3 * faces);
    twins_.reserve(3 * faces);
  }
  void set_vertex_count(std::size_t n) { vertex_half_edges_.resize(n, kNone); }
  // The corners stay (is_live, origin, next are arithmetic on them): 28 of 52 bytes a point go.
  void drop_adjacency() {
    release(twins_);
    release(vertex_half_edges_);
    release(ring_origins_);
    release(ring_across_);
    release(fan_);
  }

  HalfEdge init_sphere(VertexId a, VertexId b, VertexId c, VertexId outer) {
    assert(face_capacity() == 0);
    const FaceId inner = new_face(a, b, c);
    const FaceId fab = new_face(b, a, outer);
    const FaceId fbc = new_face(c, b, outer);
    const FaceId fca = new_face(a, c, outer);
    link(3 * inner + 0, 3 * fab + 0, false);
    link(3 * inner + 1, 3 * fbc + 0, false);
    link(3 * inner + 2, 3 * fca + 0, false);
    // Around `outer`: (b,a,o) (c,b,o) (a,c,o).
    link(3 * fab + 1, 3 * fca + 2, false);  // a->o  with o->a
    link(3 * fbc + 1, 3 * fab + 2, false);  // b->o  with o->b
    link(3 * fca + 1, 3 * fbc + 2, false);  // c->o  with o->c
    return 3 * inner;
  }

  HalfEdge flip(HalfEdge h) {
    // Face-local indices computed once: this runs about three times per inserted point.
    const FaceId f = h / 3, g = (twins_[h] & kTwinMask) / 3;
    const HalfEdge t = twins_[h] & kTwinMask;
    assert(t != kTwinMask);
    const unsigned i = h - 3 * f, j = t - 3 * g;
    const unsigned i1 = kNext[i], i2 = kNext[i1], j1 = kNext[j], j2 = kNext[j1];
    const VertexId a = vertices_[3 * f + i], b = vertices_[3 * f + i1], c = vertices_[3 * f + i2];
    const VertexId d = vertices_[3 * g + j2];
    // Outer edges of the quadrilateral a, d, b, c and what lies across them.
    const std::uint32_t across_bc = twins_[3 * f + i1], across_ca = twins_[3 * f + i2];
    const std::uint32_t across_ad = twins_[3 * g + j1], across_db = twins_[3 * g + j2];
    set_face(f, c, a, d);  // c->a, a->d, d->c
    set_face(g, d, b, c);  // d->b, b->c, c->d
    relink(3 * f + 0, across_ca);
    relink(3 * f + 1, across_ad);
    relink(3 * g + 0, across_db);
    relink(3 * g + 1, across_bc);
    link(3 * f + 2, 3 * g + 2, false);
    return 3 * g + 2;
  }

  HalfEdge split_face(FaceId f, VertexId v) {
    const VertexId a = vertices_[3 * f], b = vertices_[3 * f + 1], c = vertices_[3 * f + 2];
    const std::uint32_t across_ab = twins_[3 * f], across_bc = twins_[3 * f + 1],
                        across_ca = twins_[3 * f + 2];
    const FaceId g1 = new_face(b, c, v);
    const FaceId g2 = new_face(c, a, v);
    set_face(f, a, b, v);
    relink(3 * f + 0, across_ab);
    relink(3 * g1 + 0, across_bc);
    relink(3 * g2 + 0, across_ca);
    link(3 * f + 1, 3 * g1 + 2, false);   // b->v with v->b
    link(3 * g1 + 1, 3 * g2 + 2, false);  // c->v with v->c
    link(3 * g2 + 1, 3 * f + 2, false);   // a->v with v->a
    return 3 * f + 2;
  }

  HalfEdge split_edge(HalfEdge h, VertexId v) {
    const HalfEdge t = twin(h);
    const bool constrained = is_constrained(h);
    const FaceId f = face(h);
    const VertexId a = origin(h), b = dest(h), c = apex(h);
    const std::uint32_t across_bc = twins_[next(h)], across_ca = twins_[prev(h)];
    // f becomes (a, v, c); f2 = (v, b, c).
    const FaceId f2 = new_face(v, b, c);
    set_face(f, a, v, c);
    relink(3 * f + 2, across_ca);
    relink(3 * f2 + 1, across_bc);
    link(3 * f + 1, 3 * f2 + 2, false);  // v->c with c->v
    if (t == kNone) {
      twins_[3 * f] = kTwinMask | (constrained ? kConstrainedBit : 0);
      twins_[3 * f2] = kTwinMask | (constrained ? kConstrainedBit : 0);
      return 3 * f2;
    }
    const FaceId g = face(t);
    const VertexId d = apex(t);
    const std::uint32_t across_ad = twins_[next(t)], across_db = twins_[prev(t)];
    // g becomes (b, v, d); g2 = (v, a, d).
    const FaceId g2 = new_face(v, a, d);
    set_face(g, b, v, d);
    relink(3 * g + 2, across_db);
    relink(3 * g2 + 1, across_ad);
    link(3 * g + 1, 3 * g2 + 2, false);   // v->d with d->v
    link(3 * f + 0, 3 * g2 + 0, constrained);  // a->v with v->a
    link(3 * f2 + 0, 3 * g + 0, constrained);  // v->b with b->v
    return 3 * f2;
  }

  HalfEdge star_cavity(std::span<const HalfEdge> ring, std::span<const FaceId> faces,
                       VertexId v) {
    const std::size_t k = ring.size();
    ring_origins_.resize(k);
    ring_across_.resize(k);
    for (std::size_t i = 0; i < k; ++i) {
      ring_origins_[i] = origin(ring[i]);
      ring_across_[i] = twins_[ring[i]];
    }
    fan_.clear();
    for (std::size_t i = 0; i < k; ++i) {
      const VertexId u = ring_origins_[i], w = ring_origins_[(i + 1) % k];
      if (i < faces.size()) {
        set_face(faces[i], u, w, v);
        fan_.push_back(faces[i]);
      } else {
        fan_.push_back(new_face(u, w, v));
      }
    }
    for (std::size_t i = k; i < faces.size(); ++i) kill_face(faces[i]);
    for (std::size_t i = 0; i < k; ++i) {
      relink(3 * fan_[i] + 0, ring_across_[i]);
      link(3 * fan_[i] + 1, 3 * fan_[(i + 1) % k] + 2, false);  // w->v with v->w
    }
    return 3 * fan_[0] + 2;
  }

  HalfEdge merge_star(HalfEdge h) {
    // h = v->a in (v, a, b); going counterclockwise round v: (v, b, c), then (v, c, a).
    const HalfEdge h1 = twin(prev(h)), h2 = twin(prev(h1));
    assert(h1 != kNone && h2 != kNone && twin(prev(h2)) == h);
    const HalfEdge r0 = next(h), r1 = next(h1), r2 = next(h2);
    const VertexId v = origin(h), a = origin(r0), b = origin(r1), c = origin(r2);
    const std::uint32_t across_ab = twins_[r0], across_bc = twins_[r1], across_ca = twins_[r2];
    const FaceId f = face(h);
    kill_face(face(h1));
    kill_face(face(h2));
    set_face(f, a, b, c);
    relink(3 * f + 0, across_ab);
    relink(3 * f + 1, across_bc);
    relink(3 * f + 2, across_ca);
    if (v == kInfiniteVertex) infinite_half_edge_ = kNone;
    else vertex_half_edges_[v] = kNone;
    return 3 * f;
  }

  void remove_face(FaceId f) {
    for (int i = 0; i < 3; ++i) {
      const HalfEdge t = twin(3 * f + i);
      if (t != kNone) twins_[t] |= kTwinMask;  // keeps t's constraint bit
    }
    kill_face(f);
  }

  void rebuild_vertex_half_edges() {
    std::fill(vertex_half_edges_.begin(), vertex_half_edges_.end(), kNone);
    infinite_half_edge_ = kNone;
    for (FaceId f = 0; f < face_capacity(); ++f)
      if (is_live(f)) set_face(f, vertices_[3 * f], vertices_[3 * f + 1], vertices_[3 * f + 2]);
  }

  void set_constrained(HalfEdge h, bool constrained) {
    set_bit(h, constrained);
    const HalfEdge t = twin(h);
    if (t != kNone) set_bit(t, constrained);
  }

 private:
  static constexpr std::uint32_t kConstrainedBit = 0x80000000u;
  static constexpr unsigned kNext[3] = {1, 2, 0};
  static constexpr std::uint32_t kTwinMask = 0x7FFFFFFFu;  // also "no twin"

  void set_bit(HalfEdge h, bool on) {
    twins_[h] = on ? (twins_[h] | kConstrainedBit) : (twins_[h] & kTwinMask);
  }

  void note_vertex(VertexId v, HalfEdge h) {
    if (v == kInfiniteVertex)
      infinite_half_edge_ = h;
    else
      vertex_half_edges_[v] = h;
  }

  void set_face(FaceId f, VertexId a, VertexId b, VertexId c) {
    vertices_[3 * f] = a;
    vertices_[3 * f + 1] = b;
    vertices_[3 * f + 2] = c;
    note_vertex(a, 3 * f);
    note_vertex(b, 3 * f + 1);
    note_vertex(c, 3 * f + 2);
  }

  FaceId new_face(VertexId a, VertexId b, VertexId c) {
    FaceId f;
    if (!free_faces_.empty()) {
      f = free_faces_.back();
      free_faces_.pop_back();
    } else {
      f = static_cast<FaceId>(face_capacity());
      for (int i = 0; i < 3; ++i) {
        vertices_.push_back(kNone);
        twins_.push_back(kTwinMask);
      }
    }
    set_face(f, a, b, c);
    return f;
  }

  void kill_face(FaceId f) {
    vertices_[3 * f] = kNone;
    free_faces_.push_back(f);
  }

  // h and t become twins; both carry the constraint flag.
  void link(HalfEdge h, HalfEdge t, bool constrained) {
    const std::uint32_t bit = constrained ? kConstrainedBit : 0;
    twins_[h] = t | bit;
    twins_[t] = h | bit;
  }

  // h takes the place of the half-edge whose stored slot was `across` (twin + flag).
  void relink(HalfEdge h, std::uint32_t across) {
    twins_[h] = across;
    const std::uint32_t t = across & kTwinMask;
    if (t != kTwinMask) twins_[t] = h | (across & kConstrainedBit);
  }

  HugeArray<VertexId> vertices_;     // 3 per face; vertices_[3f] == kNone marks a dead face
  HugeArray<std::uint32_t> twins_;   // 3 per face: twin half-edge | constraint bit
  HugeArray<HalfEdge> vertex_half_edges_;
  HalfEdge infinite_half_edge_ = kNone;
  std::vector<FaceId> free_faces_;
  // Scratch for star_cavity, kept to avoid allocating per insertion.
  std::vector<VertexId> ring_origins_;
  std::vector<std::uint32_t> ring_across_;
  std::vector<FaceId> fan_;
};

}  // namespace meshstep
