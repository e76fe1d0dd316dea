// Half-edge data structure (DCEL): the second model of the TriangleMesh concept.
//
// Half-edges come in pairs, one pair per undirected edge: pair e owns half-edges 2e and
// 2e+1, so the opposite half-edge of h is h ^ 1 and is never stored. Per half-edge the
// structure stores origin, next and face (struct of arrays, 32-bit each); per face one of
// its half-edges; per vertex one outgoing half-edge. The edge's constraint flag is the top
// bit of next_ on both half-edges of its pair. For a triangulation with 2 faces and 3 edges
// per vertex that is 6*12 + 2*4 + 4 = 84 bytes per vertex (the Tds: 2*24 + 4 = 52).
//
// Both sides of every pair exist even on a boundary: after remove_face the outer side of a
// boundary edge is a faceless half-edge (face kNone, no next) that still knows its origin,
// so dest(h) = origin(h ^ 1) needs no special case. The concept never sees faceless
// half-edges: twin() answers kNone for them, and vertex_half_edge() never names one. A pair
// with no face on either side is freed. Freed pairs and freed faces are kept on intrusive
// free lists threaded through their own (otherwise unused) slots, so the lists cost no
// memory and taking from them never allocates.
#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "meshstep/huge_array.hpp"
#include "meshstep/mesh/handles.hpp"
#include "meshstep/release.hpp"

namespace meshstep {

class Dcel {
 public:
  static constexpr const char* kName = "dcel";

  // Navigation ----------------------------------------------------------------------------
  // One or two loads, no branch (twin's test compiles to a conditional move): these sit in
  // the innermost loops of point location and legalization. What a legalization test needs
  // of an edge (twin, flag, next of both sides) comes from one cache line of next_, and its
  // endpoints from one line of origin_.
  VertexId origin(HalfEdge h) const { return origin_[h]; }
  // The opposite half-edge starts where h ends and sits next to h in origin_, which beats
  // origin(next(h)) and its dependent load.
  VertexId dest(HalfEdge h) const { return origin_[h ^ 1]; }
  VertexId apex(HalfEdge h) const { return origin_[next(h) ^ 1]; }  // dest(next(h))
  HalfEdge next(HalfEdge h) const { return next_[h] & kLinkMask; }
  HalfEdge prev(HalfEdge h) const { return next(next(h)); }  // faces are triangles
  // A faceless half-edge has no next (kLinkMask); reading that from next_[h ^ 1] rather
  // than face_[h ^ 1] keeps twin() on the cache line next() uses.
  HalfEdge twin(HalfEdge h) const {
    const HalfEdge t = h ^ 1;
    return (next_[t] & kLinkMask) == kLinkMask ? kNone : t;
  }
  FaceId face(HalfEdge h) const { return face_[h]; }
  HalfEdge half_edge(FaceId f) const { return face_half_edge_[f]; }
  HalfEdge vertex_half_edge(VertexId v) const { return vertex_half_edge_[slot(v)]; }
  bool is_constrained(HalfEdge h) const { return (next_[h] & kConstrainedBit) != 0; }
  std::uint32_t corner(HalfEdge h) const {
    const HalfEdge first = half_edge(face(h));
    return h == first ? 0 : h == next(first) ? 1 : 2;
  }
  std::uint32_t constraint_mask(FaceId f) const {
    const HalfEdge h = half_edge(f), n = next(h);
    return std::uint32_t{is_constrained(h)} | std::uint32_t{is_constrained(n)} << 1 |
           std::uint32_t{is_constrained(next(n))} << 2;
  }

  // Size ----------------------------------------------------------------------------------
  std::size_t face_capacity() const { return face_half_edge_.size(); }
  std::size_t face_count() const { return live_faces_; }
  // face(h) of a stale handle can be kNone here (a freed or faceless half-edge), where the
  // Tds always names some face slot; answering false keeps `is_live(face(h))` a safe test
  // for "h still names a half-edge of a face" on both structures. (Tested against kNone,
  // not the size: a size test made GCC 12 warn falsely in code that inlines this.)
  bool is_live(FaceId f) const {
    return f != kNone && (face_half_edge_[f] & kDeadFace) == 0;
  }
  std::size_t memory_bytes() const {
    return origin_.capacity() * sizeof(VertexId) + next_.capacity() * sizeof(HalfEdge) +
           face_.capacity() * sizeof(FaceId) + face_half_edge_.capacity() * sizeof(HalfEdge) +
           vertex_half_edge_.capacity() * sizeof(HalfEdge) +
           spokes_.capacity() * sizeof(HalfEdge);
  }

  // Beyond the concept: edge pairs, for tests and memory accounting.
  std::size_t edge_capacity() const { return origin_.size() / 2; }  // pairs ever allocated
  std::size_t edge_count() const { return live_edges_; }            // pairs in use

  // Construction and mutation ---------------------------------------------------------------
  void reserve(std::size_t vertices, std::size_t faces) {
    vertex_half_edge_.reserve(vertices + kSlotOffset);
    face_half_edge_.reserve(faces);
    // A closed surface has 3F/2 edges, so 3F half-edges.
    origin_.reserve(3 * faces);
    next_.reserve(3 * faces);
    face_.reserve(3 * faces);
  }
  void set_vertex_count(std::size_t n) { vertex_half_edge_.resize(n + kSlotOffset, kNone); }
  // origin_, next_ and the faces' half-edges stay (dest and apex read origin_ through them).
  void drop_adjacency() {
    release(face_);
    release(vertex_half_edge_);
    release(spokes_);
  }

  HalfEdge init_sphere(VertexId a, VertexId b, VertexId c, VertexId outer) {
    assert(face_capacity() == 0 && edge_capacity() == 0);
    const HalfEdge ab = new_pair(a, b), bc = new_pair(b, c), ca = new_pair(c, a);
    const HalfEdge ao = new_pair(a, outer), bo = new_pair(b, outer), co = new_pair(c, outer);
    make_face(new_face(), ab, bc, ca);          // (a, b, c)
    make_face(new_face(), ab ^ 1, ao, bo ^ 1);  // (b, a, o)
    make_face(new_face(), bc ^ 1, bo, co ^ 1);  // (c, b, o)
    make_face(new_face(), ca ^ 1, co, ao ^ 1);  // (a, c, o)
    note_vertex(a, ab);
    note_vertex(b, bc);
    note_vertex(c, ca);
    note_vertex(outer, ao ^ 1);
    return ab;
  }

  // The six half-edges of the quadrilateral are relinked in place; the edge pair of h
  // becomes the new diagonal, so nothing is allocated or freed.
  HalfEdge flip(HalfEdge h) {
    const HalfEdge t = h ^ 1;
    assert(face_[h] != kNone && face_[t] != kNone);
    const FaceId f = face_[h], g = face_[t];
    const HalfEdge hn = next(h), hp = next(hn);  // b->c, c->a
    const HalfEdge tn = next(t), tp = next(tn);  // a->d, d->b
    const VertexId a = origin_[h], b = origin_[t];
    const VertexId c = origin_[hp], d = origin_[tp];
    // h: c->d closes (d, b, c) in f; t: d->c closes (c, a, d) in g. The diagonal is a new
    // edge, so its flag is cleared (as in the Tds); the outer four keep theirs.
    origin_[h] = c;
    origin_[t] = d;
    next_[h] = tp;
    next_[t] = hp;
    link_next(tp, hn);
    link_next(hn, h);
    link_next(hp, tn);
    link_next(tn, t);
    face_[tp] = f;
    face_[hp] = g;
    face_half_edge_[f] = h;
    face_half_edge_[g] = t;
    // a and b lost h and t; c and d keep whatever they had (hp, tp still leave them).
    note_vertex(a, tn);
    note_vertex(b, hn);
    return h;
  }

  HalfEdge split_face(FaceId f, VertexId v) {
    const HalfEdge e0 = face_half_edge_[f], e1 = next(e0), e2 = next(e1);
    const VertexId a = origin_[e0], b = origin_[e1], c = origin_[e2];
    // Spokes, each named by its half-edge leaving v.
    const HalfEdge va = new_pair(v, a), vb = new_pair(v, b), vc = new_pair(v, c);
    make_face(f, e0, vb ^ 1, va);           // (a, b, v)
    make_face(new_face(), e1, vc ^ 1, vb);  // (b, c, v)
    make_face(new_face(), e2, va ^ 1, vc);  // (c, a, v)
    note_vertex(v, va);
    return va;
  }

  HalfEdge split_edge(HalfEdge h, VertexId v) {
    const HalfEdge t = h ^ 1;
    const FaceId f = face_[h];
    assert(f != kNone);
    const HalfEdge hn = next(h), hp = next(hn);  // b->c, c->a
    const VertexId b = origin_[t], c = origin_[hp];
    const bool boundary = twin(h) == kNone;
    // The pair of h keeps the a-v half (a->v, v->a) with its flag; vb is the v-b half.
    const HalfEdge vb = new_pair(v, b);
    if (is_constrained(h)) set_flag(vb, true);
    origin_[t] = v;
    const HalfEdge vc = new_pair(v, c);
    make_face(f, h, vc, hp);                // (a, v, c)
    make_face(new_face(), vb, hn, vc ^ 1);  // (v, b, c)
    note_vertex(v, vb);
    // b may have been known by t, which now leaves v.
    note_vertex(b, hn);
    if (boundary) return vb;  // t and vb^1 stay faceless
    const FaceId g = face_[t];
    const HalfEdge tn = next(t), tp = next(tn);  // a->d, d->b
    const VertexId d = origin_[tp];
    const HalfEdge vd = new_pair(v, d);
    make_face(g, vb ^ 1, vd, tp);           // (b, v, d)
    make_face(new_face(), t, tn, vd ^ 1);   // (v, a, d)
    return vb;
  }

  // The ring half-edges survive (their pairs with the outside, flags included); the
  // half-edges of the cavity's interior edges are freed, then the spokes are taken from
  // the free list, so a cavity of k-2 faces costs 3 fresh pairs and 2 fresh faces net.
  HalfEdge star_cavity(std::span<const HalfEdge> ring, std::span<const FaceId> faces,
                       VertexId v) {
    const std::size_t k = ring.size();
    assert(k >= 3);
    // Tag the ring so the interior half-edges of the cavity faces can be told apart.
    for (const HalfEdge r : ring) face_[r] = kRingTag;
    for (const FaceId f : faces) {
      const HalfEdge e0 = face_half_edge_[f], e1 = next(e0), e2 = next(e1);
      // Each interior edge is seen from both of its sides; free it from its even one.
      free_if_interior(e0);
      free_if_interior(e1);
      free_if_interior(e2);
    }
    spokes_.resize(k);
    for (std::size_t i = 0; i < k; ++i) spokes_[i] = new_pair(v, origin_[ring[i]]);
    for (std::size_t i = 0; i < k; ++i) {
      const FaceId f = i < faces.size() ? faces[i] : new_face();
      const std::size_t j = i + 1 == k ? 0 : i + 1;
      make_face(f, ring[i], spokes_[j] ^ 1, spokes_[i]);  // (u_i, u_j, v)
      // u_i's outgoing half-edge may have been an interior edge just freed.
      note_vertex(origin_[ring[i]], ring[i]);
    }
    for (std::size_t i = k; i < faces.size(); ++i) free_face(faces[i]);
    note_vertex(v, spokes_[0]);
    return spokes_[0];
  }

  // Leaves vertex_half_edge() stale for the face's vertices (the concept allows it until
  // rebuild_vertex_half_edges).
  HalfEdge merge_star(HalfEdge h) {
    // h = v->a in (v, a, b); going counterclockwise round v: (v, b, c), then (v, c, a).
    const HalfEdge r0 = next(h), h1 = next(r0) ^ 1;
    const HalfEdge r1 = next(h1), h2 = next(r1) ^ 1;
    const HalfEdge r2 = next(h2);
    assert(next(r2) == (h ^ 1));
    const VertexId v = origin_[h];
    const FaceId f = face_[h];
    const FaceId g1 = face_[h1], g2 = face_[h2];
    make_face(f, r0, r1, r2);
    note_vertex(origin_[r0], r0);
    note_vertex(origin_[r1], r1);
    note_vertex(origin_[r2], r2);
    free_pair(h >> 1);
    free_pair(h1 >> 1);
    free_pair(h2 >> 1);
    free_face(g1);
    free_face(g2);
    vertex_half_edge_[slot(v)] = kNone;
    return r0;
  }

  void remove_face(FaceId f) {
    const HalfEdge e0 = face_half_edge_[f], e1 = next(e0), e2 = next(e1);
    detach(e0);
    detach(e1);
    detach(e2);
    free_face(f);
  }

  void rebuild_vertex_half_edges() {
    std::fill(vertex_half_edge_.begin(), vertex_half_edge_.end(), kNone);
    for (FaceId f = 0; f < face_capacity(); ++f) {
      if (!is_live(f)) continue;
      const HalfEdge e0 = face_half_edge_[f], e1 = next(e0), e2 = next(e1);
      note_vertex(origin_[e0], e0);
      note_vertex(origin_[e1], e1);
      note_vertex(origin_[e2], e2);
    }
  }

  void set_constrained(HalfEdge h, bool constrained) { set_flag(h, constrained); }

 private:
  // next_ holds next | constraint flag; a faceless half-edge's next is kLinkMask.
  static constexpr std::uint32_t kConstrainedBit = 0x80000000u;
  static constexpr std::uint32_t kLinkMask = 0x7FFFFFFFu;
  // A dead face's slot holds this bit plus the next dead face; kFreeEnd ends both free
  // lists.
  static constexpr std::uint32_t kDeadFace = 0x80000000u;
  static constexpr std::uint32_t kFreeEnd = 0x7FFFFFFFu;
  // Marks ring half-edges during star_cavity; never a face id (face ids stay below 2^31).
  static constexpr std::uint32_t kRingTag = 0xFFFFFFFEu;
  // vertex_half_edge_ is indexed by v + 2 in 32-bit arithmetic: kInfiniteVertex wraps to
  // slot 0 (and kNone to slot 1), so the vertex at infinity needs no branch.
  static constexpr std::size_t kSlotOffset = 2;
  static std::uint32_t slot(VertexId v) { return v + static_cast<std::uint32_t>(kSlotOffset); }

  void note_vertex(VertexId v, HalfEdge h) {
    assert(slot(v) < vertex_half_edge_.size());  // set_vertex_count first
    vertex_half_edge_[slot(v)] = h;
  }

  // Both half-edges of h's pair.
  void set_flag(HalfEdge h, bool on) {
    const std::uint32_t bit = on ? kConstrainedBit : 0;
    next_[h] = (next_[h] & kLinkMask) | bit;
    next_[h ^ 1] = (next_[h ^ 1] & kLinkMask) | bit;
  }

  // next(x) = y, keeping x's flag.
  void link_next(HalfEdge x, HalfEdge y) { next_[x] = (next_[x] & kConstrainedBit) | y; }

  // x -> y -> z -> x around face f.
  void make_face(FaceId f, HalfEdge x, HalfEdge y, HalfEdge z) {
    link_next(x, y);
    link_next(y, z);
    link_next(z, x);
    face_[x] = f;
    face_[y] = f;
    face_[z] = f;
    face_half_edge_[f] = x;
  }

  // A fresh unconstrained, faceless pair u->w / w->u; returns u->w.
  HalfEdge new_pair(VertexId u, VertexId w) {
    ++live_edges_;
    if (free_edge_ != kFreeEnd) {
      const std::uint32_t e = free_edge_;
      free_edge_ = next_[2 * e];
      const HalfEdge h = 2 * e;
      origin_[h] = u;
      origin_[h + 1] = w;
      next_[h] = kLinkMask;
      next_[h + 1] = kLinkMask;
      face_[h] = kNone;
      face_[h + 1] = kNone;
      return h;
    }
    const HalfEdge h = static_cast<HalfEdge>(origin_.size());
    assert(h < kLinkMask - 1);  // half-edge ids must stay below kLinkMask
    origin_.push_back(u);
    origin_.push_back(w);
    next_.push_back(kLinkMask);
    next_.push_back(kLinkMask);
    face_.push_back(kNone);
    face_.push_back(kNone);
    return h;
  }

  void free_pair(std::uint32_t e) {
    origin_[2 * e] = kNone;
    origin_[2 * e + 1] = kNone;
    face_[2 * e] = kNone;
    face_[2 * e + 1] = kNone;
    // next_[2e+1] is left alone: star_cavity frees a pair from its even side while the
    // face holding the odd side may still be waiting to be walked.
    next_[2 * e] = free_edge_;
    free_edge_ = e;
    --live_edges_;
  }

  FaceId new_face() {
    ++live_faces_;
    if (free_face_ != kFreeEnd) {
      const FaceId f = free_face_;
      free_face_ = face_half_edge_[f] & ~kDeadFace;
      return f;
    }
    face_half_edge_.push_back(kNone);
    return static_cast<FaceId>(face_half_edge_.size() - 1);
  }

  void free_face(FaceId f) {
    face_half_edge_[f] = kDeadFace | free_face_;
    free_face_ = f;
    --live_faces_;
  }

  void free_if_interior(HalfEdge h) {
    if (face_[h] != kRingTag && (h & 1) == 0) free_pair(h >> 1);
  }

  // h loses its face (keeping its flag for the side that remains); its pair goes when the
  // other side has no face either.
  void detach(HalfEdge h) {
    face_[h] = kNone;
    next_[h] |= kLinkMask;
    if (face_[h ^ 1] == kNone) free_pair(h >> 1);
  }

  HugeArray<VertexId> origin_;  // per half-edge; kNone in a freed pair
  // Per half-edge: next | kConstrainedBit; kLinkMask as next when faceless. In a freed pair
  // next_[2e] holds the next free pair.
  HugeArray<HalfEdge> next_;
  HugeArray<FaceId> face_;              // per half-edge; kNone when faceless or freed
  HugeArray<HalfEdge> face_half_edge_;  // per face; kDeadFace | next free face when dead
  HugeArray<HalfEdge> vertex_half_edge_;  // per vertex, at slot(v)
  std::uint32_t free_edge_ = kFreeEnd;
  std::uint32_t free_face_ = kFreeEnd;
  std::size_t live_edges_ = 0;
  std::size_t live_faces_ = 0;
  std::vector<HalfEdge> spokes_;  // star_cavity scratch, kept to avoid allocating per insertion
};

}  // namespace meshstep
