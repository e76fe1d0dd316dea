// A triangle mesh as plain arrays: what triangulators return, writers write, readers of
// .node/.ele read and the checker checks. Independent of the data structure that built it.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep {

inline constexpr std::uint32_t kNoIndex = 0xFFFFFFFFu;

struct TriMesh {
  // Vertices: the input vertices first, in input order (duplicates and vertices outside the
  // domain stay listed, referenced by no triangle), then Steiner vertices.
  std::vector<Point> points;
  std::size_t attributes_per_vertex = 0;
  std::vector<double> vertex_attributes;  // points.size() * attributes_per_vertex
  std::vector<int> vertex_markers;        // empty or points.size()

  // Triangles, counterclockwise, 0-based vertex indices.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // neighbors[t][i]: triangle across the edge opposite triangles[t][i], kNoIndex on the
  // boundary. Empty when not computed.
  std::vector<std::array<std::uint32_t, 3>> neighbors;
  std::size_t attributes_per_triangle = 0;  // 0 or 1 (the region attribute)
  std::vector<double> triangle_attributes;
  std::vector<double> triangle_max_area;  // empty, or per triangle (<= 0: none)

  // Constrained edges of the mesh (input segments and their pieces), with markers.
  std::vector<Segment> segments;
  bool has_segment_markers = false;
  std::vector<Point> holes;  // carried through to the output .poly
  std::vector<Region> regions;

  std::size_t input_vertex_count = 0;  // points[0, input_vertex_count) came from the input
  int first_index = 0;
};

// The vertex markers of a mesh whose first `input_count` vertices came from the input with
// `input_markers`: those kept, and each Steiner vertex given the marker of the first
// segment, in the order of mesh.segments, that ends at it (the segment it split). The
// rule of the output and of a replayed moment (Replay::output_mesh), in one place.
inline void set_vertex_markers(TriMesh& mesh, std::vector<int> input_markers, std::size_t input_count) {
  mesh.vertex_markers = std::move(input_markers);
  mesh.vertex_markers.resize(mesh.points.size(), 0);
  for (const Segment& s : mesh.segments)
    for (const std::uint32_t v : {s.a, s.b})
      if (v >= input_count && mesh.vertex_markers[v] == 0) mesh.vertex_markers[v] = s.marker;
}

}  // namespace meshstep
