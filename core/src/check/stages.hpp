// The stages of check_mesh and the facts they share. Each stage appends to the log; the
// early stages also decide which triangles and vertices the later ones may trust.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "check/box_tree.hpp"
#include "check/edge_table.hpp"
#include "check/problem_log.hpp"
#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep::check_detail {

enum class TriState : std::uint8_t {
  kBadIndices,  // out of range or repeated vertex: ignored by every later stage
  kNotCcw,      // clockwise, degenerate or non-finite: part of the topology, not the geometry
  kGood,        // strictly counterclockwise
};

struct MeshFacts {
  const TriMesh& mesh;
  ProblemLog& log;
  std::vector<TriState> tri_state;
  std::vector<std::uint8_t> finite_point;  // both coordinates finite
  std::optional<EdgeTable> edges;          // built after indices are known to be sane
  std::vector<std::uint8_t> listed_edge;   // per edge id: the edge is one of mesh.segments
  std::optional<BoxTree> good_triangles;   // built on first use by triangle_tree()

  bool usable(std::size_t t) const { return tri_state[t] != TriState::kBadIndices; }
  bool good(std::size_t t) const { return tri_state[t] == TriState::kGood; }
  std::string vertex(std::size_t v) const { return number(v, mesh.first_index); }
  std::string triangle(std::size_t t) const;  // "triangle 4 (vertices 1 5 2)"
  // Fills listed_edge from mesh.segments (needs edges).
  void mark_listed_edges();
  // Is the mesh edge between v and w (either direction) listed in mesh.segments?
  bool is_listed(std::uint32_t v, std::uint32_t w) const;
  // A box tree of the good triangles, for the input stages' spatial queries. Built only
  // when needed: a mesh whose segments are all covered never asks.
  const BoxTree& triangle_tree();
};

// Stage 1: vertex coordinates, triangle and segment indices, duplicate triangles.
void check_indices(MeshFacts& facts);
// Stage 2: strict counterclockwise orientation (exact).
void check_orientation(MeshFacts& facts);
// Stage 3: every undirected edge used at most twice, and then in opposite directions.
void check_edge_use(MeshFacts& facts);
// Stage 4a: triangles around each fully interior vertex wind exactly once.
void check_winding(MeshFacts& facts);
// Stage 4b: no vertex inside a triangle or inside one of its edges.
void check_vertices_in_triangles(MeshFacts& facts);
// Stage 5: every unconstrained interior edge is locally Delaunay.
void check_delaunay(MeshFacts& facts);
// Stage 6: stored neighbors agree with the triangles.
void check_neighbors(MeshFacts& facts);
// Stage 7a: input vertices kept first, in order, bit for bit.
void check_input_vertices(MeshFacts& facts, const Pslg& input);
// Stage 7b: every input segment is covered by a chain of mesh edges (listed as segments).
void check_input_segments(MeshFacts& facts, const Pslg& input);
// Stage 7c: no hole point lies inside a remaining triangle.
void check_input_holes(MeshFacts& facts, const Pslg& input);

}  // namespace meshstep::check_detail
