// Puts a triangle surface into a mesh structure (any TriangleMesh) through the concept's
// own operations, for surfaces of any genus, with or without borders, in any number of
// pieces.
//
// The concept has no "add this triangle": a mesh starts as init_sphere and changes by
// splits and flips, which keep it a sphere. So the loader grows the surface inside a
// sphere, triangle by triangle, the rest of the sphere made of scaffold faces round a hub
// node (id kInfiniteVertex):
//   - a triangle beside one built triangle is split out of the scaffold face across their
//     common edge (split_face, the new node taking the triangle's third vertex id);
//   - a triangle beside two built triangles whose scaffold faces meet at the edge between
//     them is made by flipping that edge (an "ear": both sides are joined at once);
//   - the first triangle of the first piece is init_sphere's, and the first of each later
//     piece is split out of a scaffold face at the hub (start_piece).
// Vertex ids are only labels here: a vertex met again where the scaffold cannot reach it
// gets a second node with the same id, and the edge between the two copies is a seam
// (seam_table.hpp). That happens at the last hole of a closed piece (never closed, which
// would need the hub to go), round the handles of a torus, along a path from where a later
// piece is bridged to the rest of the scaffold, and at pinches of the growth. Growing ears
// first keeps the front short and the seams few: one for a sphere, the cut of a torus. At
// the end the scaffold faces are removed, and the mesh's borders are the surface's borders
// and the seams.
//
// Built triangles are never touched again while loading, so the half-edges each was given
// stay valid to the end.
#pragma once

#include <array>
#include <cassert>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "edge_neighbours.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/mesh/concept.hpp"
#include "meshstep/replay/recorder.hpp"
#include "seam_table.hpp"

namespace meshstep::surface::detail {

// Rec records every change into a replay log (replay/recorder.hpp): the loading is then the
// run's first step, scaffold and all (the scaffold faces are ghost faces: a replay's mesh
// leaves them out, and shows the surface growing triangle by triangle).
template <TriangleMesh Mesh, class Rec = replay::NullRecorder>
class SurfaceLoader {
 public:
  SurfaceLoader(const io::Surface& surface, Mesh& mesh, SeamTable& seams, Rec& rec)
      : triangles_(surface.triangles), mesh_(mesh), seams_(seams), rec_(rec),
        opposite_(opposite_corner_edges(surface.triangles)),
        half_edge_(3 * triangles_.size(), kNone), built_neighbours_(triangles_.size(), 0) {
    mesh_.set_vertex_count(surface.vertices.size());
    // The scaffold about doubles the faces while loading.
    mesh_.reserve(surface.vertices.size(), 2 * triangles_.size() + 4);
  }

  void run() {
    for (std::uint32_t t = 0; t < triangles_.size(); ++t) {
      if (built(t)) continue;  // its piece is done
      start_piece(t);
      grow_piece();
    }
    remove_scaffold();
    register_seams();
  }

 private:
  using Triangle = std::array<std::uint32_t, 3>;

  // The scaffold's hub: the one node with this id, never a vertex of the surface, and
  // never removed while loading, so the mesh always knows a half-edge leaving it.
  static constexpr VertexId kHub = kInfiniteVertex;

  bool built(std::uint32_t t) const { return half_edge_[3 * t] != kNone; }

  // The half-edge that the built neighbour across corner edge c of an unbuilt triangle
  // gave to their common edge, or kNone when that neighbour is missing or not built yet.
  HalfEdge built_side_across(std::uint32_t c) const {
    const std::uint32_t o = opposite_[c];
    return o == kNone ? kNone : half_edge_[o];
  }

  // Triangles whose turn has come: ears (two or three built neighbours) before the front.
  void grow_piece() {
    for (;;) {
      std::uint32_t t;
      if (!ears_.empty()) {
        t = ears_.back();
        ears_.pop_back();
      } else if (front_head_ < front_.size()) {
        t = front_[front_head_++];
      } else {
        break;
      }
      if (!built(t)) build(t);
    }
    front_.clear();
    front_head_ = 0;
  }

  void start_piece(std::uint32_t t) {
    const Triangle& p = triangles_[t];
    if (mesh_.face_capacity() == 0) {
      static_assert(kHub == kInfiniteVertex, "the recorder's init_sphere joins the triangle to kInfiniteVertex");
      mark_built(t, 0, rec_.init_sphere(mesh_, p[0], p[1], p[2]));
      return;
    }
    // A later piece is split out of a scaffold face (o, x, y) at the hub o, as the fan
    // round o that the first piece had, but for a bridge of scaffold to the rest at one
    // corner: ears then close at the other two corners as they do in the first piece.
    // Nodes n0, n1, n2 get the triangle's ids p[0], p[1], p[2]. A face is found again
    // after it changed through the twin of one of its edges: that half-edge lies in a face
    // the change does not touch, so it keeps its id.
    const HalfEdge ox = mesh_.vertex_half_edge(kHub);
    const HalfEdge outside_ox = mesh_.twin(ox);
    rec_.split_face(mesh_, mesh_.face(ox), p[1]);  // (x, y, n1) (y, o, n1) (o, x, n1)
    const HalfEdge ox1 = mesh_.twin(outside_ox);                  // o->x in (o, x, n1)
    const HalfEdge n1_x = mesh_.twin(mesh_.next(ox1));            // in (x, y, n1)
    const HalfEdge o_n1 = mesh_.twin(mesh_.prev(ox1));            // in (y, o, n1)
    rec_.split_face(mesh_, mesh_.face(ox1), p[0]);  // (o, x, n0) (x, n1, n0) (n1, o, n0)
    const HalfEdge n1_o = mesh_.twin(o_n1);                       // in (n1, o, n0)
    const HalfEdge n1_n0 = mesh_.twin(mesh_.prev(n1_o));          // in (x, n1, n0)
    rec_.split_face(mesh_, mesh_.face(n1_o), p[2]);  // (n1, o, n2) (o, n0, n2) (n0, n1, n2)
    const HalfEdge triangle = mesh_.twin(n1_n0);                  // n0->n1 in (n0, n1, n2)
    // n1 has four scaffold faces round it; two flips leave it the two of the fan.
    const HalfEdge y_n0 = rec_.flip(mesh_, n1_x, replay::FlipReason::load);  // (y, n1, n0) (n0, x, y)
    rec_.flip(mesh_, mesh_.next(mesh_.twin(y_n0)), replay::FlipReason::load);  // y->n1: (o, n1, n0) (n0, y, o)
    mark_built(t, 0, triangle);
  }

  void build(std::uint32_t t) {
    const Triangle& p = triangles_[t];
    // sides[i]: the built neighbour's half-edge along edge i (p[i+1] -> p[i]); its twin
    // lies in the scaffold face across which this triangle will be made.
    std::array<HalfEdge, 3> sides{};
    for (std::uint32_t i = 0; i < 3; ++i) sides[i] = built_side_across(3 * t + i);
    // An ear: edges i and i+1 both built, their scaffold faces sharing the edge that leaves
    // p[i+1]. Flipping it makes (p[i], p[i+1], p[i+2]) out of the two faces.
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t j = (i + 1) % 3;
      if (sides[i] == kNone || sides[j] == kNone) continue;
      const HalfEdge gi = mesh_.twin(sides[i]), gj = mesh_.twin(sides[j]);
      const HalfEdge shared = mesh_.next(gi);
      if (mesh_.twin(shared) != mesh_.prev(gj)) continue;
      rec_.flip(mesh_, shared, replay::FlipReason::load);
      mark_built(t, i, mesh_.twin(sides[i]));
      return;
    }
    for (std::uint32_t i = 0; i < 3; ++i) {
      if (sides[i] == kNone) continue;
      rec_.split_face(mesh_, mesh_.face(mesh_.twin(sides[i])), p[(i + 2) % 3]);
      mark_built(t, i, mesh_.twin(sides[i]));
      return;
    }
    assert(false && "a triangle is built beside a built neighbour");
  }

  // Triangle t is built, h its half-edge from corner i to corner i+1.
  void mark_built(std::uint32_t t, std::uint32_t i, HalfEdge h) {
    half_edge_[3 * t + i] = h;
    half_edge_[3 * t + (i + 1) % 3] = mesh_.next(h);
    half_edge_[3 * t + (i + 2) % 3] = mesh_.prev(h);
    const FaceId f = mesh_.face(h);
    if (is_surface_.size() < mesh_.face_capacity()) is_surface_.resize(2 * mesh_.face_capacity(), 0);
    is_surface_[f] = 1;
    for (std::uint32_t k = 0; k < 3; ++k) {
      assert(mesh_.origin(half_edge_[3 * t + k]) == triangles_[t][k] &&
             mesh_.dest(half_edge_[3 * t + k]) == triangles_[t][(k + 1) % 3]);
      const std::uint32_t o = opposite_[3 * t + k];
      if (o == kNone || built(o / 3)) continue;
      const std::uint32_t n = ++built_neighbours_[o / 3];
      if (n >= 2) ears_.push_back(o / 3);
      else front_.push_back(o / 3);
    }
  }

  void remove_scaffold() {
    for (FaceId f = 0; f < mesh_.face_capacity(); ++f)
      if (mesh_.is_live(f) && (f >= is_surface_.size() || !is_surface_[f])) rec_.remove_face(mesh_, f, replay::RemoveReason::ghost);
    mesh_.rebuild_vertex_half_edges();
  }

  // Edges whose two sides were built apart: after the scaffold is gone, both sides are
  // borders of the mesh, and only the table joins them.
  void register_seams() {
    for (std::uint32_t c = 0; c < half_edge_.size(); ++c) {
      const HalfEdge h = half_edge_[c];
      if (opposite_[c] == kNone || mesh_.twin(h) != kNone) continue;
      seams_.add(mesh_.origin(h), mesh_.dest(h));
      seams_.set_if_seam(mesh_.origin(h), mesh_.dest(h), h);
    }
  }

  const std::vector<Triangle>& triangles_;
  Mesh& mesh_;
  SeamTable& seams_;
  Rec& rec_;
  std::vector<std::uint32_t> opposite_;      // per corner edge (edge_neighbours.hpp)
  std::vector<HalfEdge> half_edge_;          // per corner edge, once its triangle is built
  std::vector<std::uint8_t> built_neighbours_;  // per triangle
  std::vector<std::uint8_t> is_surface_;     // per face: built triangle, not scaffold
  std::vector<std::uint32_t> ears_, front_;  // triangles waiting; front_ is a FIFO
  std::size_t front_head_ = 0;
};

// Loads `surface` into the empty `mesh`; the seams go into the empty `seams`.
template <TriangleMesh Mesh, class Rec = replay::NullRecorder>
void load_surface(const io::Surface& surface, Mesh& mesh, SeamTable& seams, Rec&& rec = Rec{}) {
  SurfaceLoader<Mesh, std::remove_cvref_t<Rec>>(surface, mesh, seams, rec).run();
}

}  // namespace meshstep::surface::detail
