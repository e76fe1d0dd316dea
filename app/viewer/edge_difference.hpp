// The difference overlay of runs side by side: the edges one mesh has and another lacks.
// Two runs number their Steiner vertices differently (and may number even their inputs'
// apart), so edges are matched by their end points' coordinates, which a replay reproduces
// bit for bit: an edge is the same edge when both ends are the same points. No GL.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::viewer {

// A mesh's edges, each once, as pairs of points (the smaller point first), sorted: what
// edges_missing compares. Triangles naming a point the mesh does not have are skipped.
struct EdgeSet {
  std::vector<std::array<Point, 2>> edges;
};
EdgeSet edge_set(const scene::MeshLayer& mesh);

// The edges of `a` that `b` does not have, in a's sorted order.
std::vector<std::array<Point, 2>> edges_missing(const EdgeSet& a, const EdgeSet& b);

}  // namespace meshstep::viewer
