// Removing a free vertex from a constrained Delaunay triangulation: the move behind
// "improvement + refinement" (Coll et al. 2008), planned and judged before the mesh is
// touched.
//
// The hole a vertex v leaves is the polygon P of its neighbours. The triangles that fill
// it are the Delaunay triangulation of P, found by clipping ears whose circumcircle holds
// no other vertex of P. The test is the triangulation's own (symbolic perturbation breaks
// cocircular ties), so that triangulation is unique and is the one Delaunay flips would
// reach: the plan is what the mesh will hold.
//
// The plan is carried out with the mesh's own moves, so that a replay steps through it:
// every planned triangle but the one that holds v is cut off as an ear, by flipping the
// spoke from v to the ear's tip: v lies beyond the ear's diagonal, so that is the flip of
// a convex quadrilateral (or, when v lies on the diagonal, as the centre of a square does,
// it leaves a flat triangle that the end of the step removes). Ears are cut until v has
// degree 3; merge_star then removes it, leaving the last planned triangle.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/geometry/predicates.hpp"
#include "meshstep/mesh/concept.hpp"

namespace meshstep {

template <TriangleMesh Mesh, class Rec>
class VertexRemover {
 public:
  using Triangle = std::array<VertexId, 3>;  // counterclockwise

  explicit VertexRemover(Triangulation<Mesh, Rec>& tri) : tri_(tri), mesh_(tri.mesh()) {}

  // Plans the removal of origin(out). False when the vertex is not free (an edge round it is
  // a segment or on the boundary), or when a constrained edge of the hole that is not
  // Delaunay leaves no ear with an empty circumcircle.
  bool plan(HalfEdge out) {
    vertex_ = mesh_.origin(out);
    ring_.clear();
    HalfEdge h = out;
    do {
      if (mesh_.twin(h) == kNone || mesh_.is_constrained(h)) return false;
      const VertexId w = mesh_.dest(h);
      if (w == kInfiniteVertex) return false;
      ring_.push_back(w);
      h = mesh_.twin(mesh_.prev(h));
      if (h == kNone) return false;
    } while (h != out);
    // The ring from its smallest vertex id: the plan then does not depend on which
    // half-edge the data structure keeps for the vertex.
    std::size_t first = 0;
    for (std::size_t i = 1; i < ring_.size(); ++i)
      if (ring_[i] < ring_[first]) first = i;
    std::rotate(ring_.begin(), ring_.begin() + static_cast<std::ptrdiff_t>(first), ring_.end());
    return triangulate_hole() && find_holder();
  }

  // After plan(): the triangles round the vertex now, and those that will replace them.
  const std::vector<Triangle>& old_triangles() {
    old_.clear();
    for (std::size_t i = 0; i < ring_.size(); ++i)
      old_.push_back({vertex_, ring_[i], ring_[(i + 1) % ring_.size()]});
    return old_;
  }
  const std::vector<Triangle>& new_triangles() const { return plan_; }

  // Carries out the plan (the caller opened the step). Returns the ring's vertices, each
  // now in a new triangle.
  const std::vector<VertexId>& apply() {
    polygon_ = ring_;
    done_.assign(plan_.size(), 0);
    done_[holder_] = 1;
    while (polygon_.size() > 3) {
      const std::size_t n = polygon_.size();
      bool cut = false;
      for (std::size_t i = 0; i < n && !cut; ++i) {
        const VertexId p = polygon_[(i + n - 1) % n], c = polygon_[i], q = polygon_[(i + 1) % n];
        for (std::size_t t = 0; t < plan_.size() && !cut; ++t) {
          if (done_[t] || !same_triangle(plan_[t], {p, c, q})) continue;
          tri_.flip(tri_.find_edge(vertex_, c), replay::FlipReason::vertex_removal);
          done_[t] = 1;
          polygon_.erase(polygon_.begin() + static_cast<std::ptrdiff_t>(i));
          cut = true;
        }
      }
      if (!cut) throw std::logic_error("vertex removal: no planned ear to cut");  // plan() rules it out
    }
    tri_.merge_star(tri_.find_edge(vertex_, polygon_[0]));
    // The planned triangles are the Delaunay ones; a constrained hole edge that is not
    // Delaunay may still leave an edge to flip beyond the hole, so the ring is checked.
    stack_.clear();
    for (std::size_t i = 0; i < ring_.size(); ++i)
      if (const HalfEdge e = tri_.find_edge(ring_[i], ring_[(i + 1) % ring_.size()]); e != kNone) stack_.push_back(e);
    tri_.make_delaunay(stack_);
    return ring_;
  }

 private:
  const Point& point(VertexId v) const { return tri_.point(v); }

  static bool same_triangle(const Triangle& t, const Triangle& u) {
    for (int r = 0; r < 3; ++r)
      if (t[r] == u[0] && t[(r + 1) % 3] == u[1] && t[(r + 2) % 3] == u[2]) return true;
    return false;
  }

  // Ear clipping: an ear (p, c, q) of the remaining polygon, convex, whose circumcircle
  // holds no other vertex of it. Such an ear contains no vertex, so its diagonal lies
  // inside the polygon; the Delaunay triangulation of the polygon always has one.
  bool triangulate_hole() {
    plan_.clear();
    polygon_ = ring_;
    while (polygon_.size() > 3) {
      const std::size_t n = polygon_.size();
      bool cut = false;
      for (std::size_t i = 0; i < n && !cut; ++i) {
        const VertexId p = polygon_[(i + n - 1) % n], c = polygon_[i], q = polygon_[(i + 1) % n];
        if (orient2d(point(p), point(c), point(q)) <= 0.0) continue;
        bool empty = true;
        for (const VertexId r : polygon_)
          if (r != p && r != c && r != q && incircle_perturbed(point(p), point(c), point(q), point(r)) > 0) {
            empty = false;
            break;
          }
        if (!empty) continue;
        plan_.push_back({p, c, q});
        polygon_.erase(polygon_.begin() + static_cast<std::ptrdiff_t>(i));
        cut = true;
      }
      if (!cut) return false;  // a constrained, non-Delaunay hole edge hides the answer
    }
    if (orient2d(point(polygon_[0]), point(polygon_[1]), point(polygon_[2])) <= 0.0) return false;
    plan_.push_back({polygon_[0], polygon_[1], polygon_[2]});
    return true;
  }

  // The planned triangle that holds the vertex (on its boundary, if the vertex lies on a
  // planned edge: then the flip that cuts the ear across that edge makes a flat triangle
  // for the rest of the step, which the merge takes away).
  bool find_holder() {
    const Point& v = point(vertex_);
    for (std::size_t t = 0; t < plan_.size(); ++t) {
      const Triangle& x = plan_[t];
      if (orient2d(point(x[0]), point(x[1]), v) >= 0.0 && orient2d(point(x[1]), point(x[2]), v) >= 0.0 &&
          orient2d(point(x[2]), point(x[0]), v) >= 0.0) {
        holder_ = t;
        return true;
      }
    }
    return false;  // not reached: the planned triangles cover the star, v inside it
  }

  Triangulation<Mesh, Rec>& tri_;
  Mesh& mesh_;
  VertexId vertex_ = kNone;
  std::vector<VertexId> ring_, polygon_;
  std::vector<Triangle> plan_, old_;
  std::size_t holder_ = 0;
  std::vector<HalfEdge> stack_;
  std::vector<std::uint8_t> done_;  // by planned triangle: cut off already (scratch, kept)
};

}  // namespace meshstep
