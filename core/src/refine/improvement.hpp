// Improvement (Coll et al. 2008): after refinement, remove the Steiner vertices whose
// removal makes their neighbourhood better, as the caller judges it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/delaunay/vertex_removal.hpp"
#include "meshstep/refine/quality.hpp"

namespace meshstep::detail {

// sin^2 of the smallest angle of the finite triangles round origin(out).
template <TriangleMesh Mesh, class Rec>
double star_quality(const Triangulation<Mesh, Rec>& tri, HalfEdge out) {
  const Mesh& m = tri.mesh();
  double worst = 1.0;
  tri.for_each_out_edge(out, [&](HalfEdge h) {
    if (m.apex(h) == kInfiniteVertex || m.dest(h) == kInfiniteVertex) return;
    worst = std::min(worst, quality::shape(tri.point(m.origin(h)), tri.point(m.dest(h)), tri.point(m.apex(h))).sin2_min_angle());
  });
  return worst;
}

// Removes every free Steiner vertex (id >= input_count) for which accept(old triangles, new
// triangles) says yes, worst neighbourhood first; the neighbours of a removed vertex are
// looked at again. Every removal takes a vertex away for good, so the pass ends. One
// recorded step per removal. Returns how many were removed.
template <TriangleMesh Mesh, class Rec, class Accept>
std::size_t remove_steiner_vertices(Triangulation<Mesh, Rec>& tri, std::size_t input_count, Accept&& accept) {
  const Mesh& mesh = tri.mesh();
  Rec& rec = tri.recorder();
  rec.phase_begin(replay::Phase::improve);
  VertexRemover<Mesh, Rec> remover(tri);
  std::vector<std::pair<double, VertexId>> worst_first;
  for (VertexId v = static_cast<VertexId>(input_count); v < tri.points().size(); ++v)
    if (const HalfEdge out = mesh.vertex_half_edge(v); out != kNone) worst_first.push_back({star_quality(tri, out), v});
  std::sort(worst_first.begin(), worst_first.end());
  std::deque<VertexId> work;
  std::vector<std::uint8_t> queued(tri.points().size(), 0);
  for (const auto& [quality, v] : worst_first) {
    work.push_back(v);
    queued[v] = 1;
  }
  std::size_t removed = 0;
  while (!work.empty()) {
    const VertexId v = work.front();
    work.pop_front();
    queued[v] = 0;
    const HalfEdge out = mesh.vertex_half_edge(v);
    if (out == kNone || !remover.plan(out) || !accept(remover.old_triangles(), remover.new_triangles())) continue;
    rec.step_begin(mesh, replay::StepKind::remove_vertex, v);
    for (const VertexId w : remover.apply())
      if (w >= input_count && !queued[w]) {
        work.push_back(w);
        queued[w] = 1;
      }
    ++removed;
  }
  rec.phase_end(replay::Phase::improve);
  return removed;
}

}  // namespace meshstep::detail
