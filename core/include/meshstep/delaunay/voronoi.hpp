// The Voronoi diagram of a Delaunay triangulation, as its dual: a Voronoi vertex per triangle
// (its circumcenter) and a Voronoi edge per mesh edge, finite between the circumcenters of
// the two triangles beside an interior edge, a ray from the one triangle's circumcenter for
// a boundary edge, pointing out of the mesh across that edge. Written as Triangle's -v
// writes it: PREFIX.v.node and PREFIX.v.edge, where an edge whose second end is -1 is a
// ray and carries its direction. For a constrained (not strictly Delaunay) mesh this is the
// mesh's dual, not the points' true Voronoi diagram, as in Triangle.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep {

struct VoronoiDiagram {
  std::vector<Point> vertices;  // vertex t: the circumcenter of the mesh's triangle t
  struct Edge {
    std::uint32_t a = 0, b = kNoIndex;  // b == kNoIndex: a ray from vertex a
    Point direction;                    // a ray's direction: the boundary edge's outward normal, as long as the edge
    // The mesh edge it crosses, by its vertices: for a ray, as the mesh's triangle runs it
    // (counterclockwise, the mesh on its left).
    std::uint32_t from = kNoIndex, to = kNoIndex;
  };
  std::vector<Edge> edges;  // one per mesh edge, in the order of the edges' (smaller, larger) vertex numbers
};

VoronoiDiagram voronoi_of(const TriMesh& mesh);
// The same of triangles (counterclockwise) over points, a scene's mesh: points that no
// triangle uses are no site.
VoronoiDiagram voronoi_of(std::span<const Point> points, std::span<const std::array<std::uint32_t, 3>> triangles);

// Writes PREFIX.v.node and PREFIX.v.edge, numbered from first_index, each atomically.
// Throws InputError("PATH: why") when a file cannot be written.
void write_voronoi(const std::string& prefix, const VoronoiDiagram& diagram, int first_index);

}  // namespace meshstep
