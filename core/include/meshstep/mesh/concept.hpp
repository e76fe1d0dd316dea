// The one interface every mesh algorithm is written against.
//
// A model stores a triangulation whose faces are triangles. Navigation is by half-edges:
// a half-edge h is a directed edge of face face(h), from origin(h) to dest(h), with the face
// on its left; apex(h) is the face's third vertex, next/prev go counterclockwise around
// the face, twin(h) is the opposite half-edge in the adjacent face (kNone on a boundary).
// Mutations keep every face counterclockwise, keep twins and constraint flags consistent
// on both sides, and keep vertex_half_edge(v) pointing at a half-edge leaving v, except
// after remove_face (call rebuild_vertex_half_edges when done removing).
//
// Handles returned before a mutation may name different elements after it; algorithms
// re-derive them from the half-edges a mutation returns. A stale half-edge is still safe
// to ask face(h) of, and is_live(face(h)) answers false when it no longer bounds a face.
//
// Constraint flags: flip makes an unconstrained diagonal; split_edge gives both halves the
// old edge's flag; star_cavity keeps the ring edges' flags and makes unconstrained spokes;
// merge_star keeps the ring edges' flags; remove_face keeps the flag on the side that remains. Call set_vertex_count before
// init_sphere; reserve() counts faces of a closed surface.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>

#include "meshstep/mesh/handles.hpp"

namespace meshstep {

template <class M>
concept TriangleMesh = requires(M& m, const M& cm, HalfEdge h, FaceId f, VertexId v,
                                std::span<const HalfEdge> ring, std::span<const FaceId> faces,
                                bool flag, std::size_t n) {
  // Navigation.
  { cm.origin(h) } -> std::same_as<VertexId>;
  { cm.dest(h) } -> std::same_as<VertexId>;
  { cm.apex(h) } -> std::same_as<VertexId>;
  { cm.next(h) } -> std::same_as<HalfEdge>;
  { cm.prev(h) } -> std::same_as<HalfEdge>;
  { cm.twin(h) } -> std::same_as<HalfEdge>;
  { cm.face(h) } -> std::same_as<FaceId>;
  { cm.half_edge(f) } -> std::same_as<HalfEdge>;
  { cm.vertex_half_edge(v) } -> std::same_as<HalfEdge>;
  { cm.is_constrained(h) } -> std::same_as<bool>;
  // Where h stands in its face: 0 for half_edge(face(h)), 1 for the next, 2 for the one
  // after; and the face's constraint flags, bit i for its i-th half-edge in that order. The
  // recorder reads both for every face a flip touches, and the Tds answers them with
  // arithmetic where next/prev chains would not fold.
  { cm.corner(h) } -> std::same_as<std::uint32_t>;
  { cm.constraint_mask(f) } -> std::same_as<std::uint32_t>;

  // Size. Face ids are below face_capacity(); dead slots answer is_live() == false.
  { cm.face_capacity() } -> std::same_as<std::size_t>;
  { cm.face_count() } -> std::same_as<std::size_t>;
  { cm.is_live(f) } -> std::same_as<bool>;
  { cm.memory_bytes() } -> std::same_as<std::size_t>;

  // Construction and mutation.
  { m.reserve(n, n) };                     // vertices, faces
  { m.set_vertex_count(n) };               // vertex ids 0..n-1 (plus kInfiniteVertex) exist
  // The closed surface of triangle (a, b, c) (counterclockwise) and three faces joining its
  // edges to `outer` (usually kInfiniteVertex). Returns the half-edge a->b. Mesh must be empty.
  { m.init_sphere(v, v, v, v) } -> std::same_as<HalfEdge>;
  // Replace the edge of h and its twin by the other diagonal of their quadrilateral;
  // returns the new half-edge from apex(h) to the apex of twin(h).
  { m.flip(h) } -> std::same_as<HalfEdge>;
  // Split a face into three around the new vertex v; returns v -> origin(half_edge(f)).
  { m.split_face(f, v) } -> std::same_as<HalfEdge>;
  // Split the edge of h (and its twin if any) at v: 2 faces become 4 (1 become 2 on the
  // boundary); both halves inherit the constraint flag. Returns the half-edge v -> dest(h).
  { m.split_edge(h, v) } -> std::same_as<HalfEdge>;
  // Replace the faces of a cavity (a topological disk without interior vertices) by the fan
  // joining v to its boundary. ring holds the boundary half-edges inside the cavity, in
  // counterclockwise order (dest of one is origin of the next). Returns v -> origin(ring[0]).
  { m.star_cavity(ring, faces, v) } -> std::same_as<HalfEdge>;
  // Remove the vertex origin(h), of degree 3 and not on the boundary: its three faces become
  // the one triangle of its neighbours. Returns a half-edge of that face. The vertex keeps
  // its id; vertex_half_edge(origin(h)) answers kNone from then on.
  { m.merge_star(h) } -> std::same_as<HalfEdge>;
  { m.remove_face(f) };
  { m.rebuild_vertex_half_edges() };
  { m.set_constrained(h, flag) };          // both sides of the edge
  // Frees what only moving across edges and round vertices needs (twin, vertex_half_edge,
  // the constraint flags, face(h) where it is stored): a mesh about to be converted and
  // destroyed makes room for its output. Afterwards only is_live, half_edge, origin, dest,
  // apex, next, prev and the sizes may be asked; anything else is undefined.
  { m.drop_adjacency() };
};

}  // namespace meshstep
