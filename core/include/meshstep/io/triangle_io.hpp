// Readers and writers for the file formats of Shewchuk's Triangle 1.6:
// .node, .poly, .ele, .area, .edge, .neigh.
//
// Reading is strict: every problem in a file is an InputError whose what() reads
// "FILE:LINE: message" (LINE 1-based; 0 when the file cannot be opened or written).
// Problems that lose nothing the caller asked for (a zero-length or duplicate segment,
// which is dropped) are reported as "FILE:LINE: message" strings in *warnings instead.
//
// Numbering: the first vertex number of the .node (or .poly) section decides whether the
// whole set of files counts from 0 or from 1; that base is stored in first_index. In
// memory every index is 0-based. Writers number from mesh.first_index.
//
// Writers write each file to a temporary file in the same folder and rename it into place,
// so a failure never leaves a half-written file behind. Coordinates, attributes and areas
// are written in the shortest form that reads back to the same double, bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep::io {

// A .node file: vertices only.
Pslg read_node(const std::string& path, std::vector<std::string>* warnings = nullptr);

// A .poly file. When its vertex section declares 0 vertices, the vertices are read from the
// .node file with the same base name in the same folder.
Pslg read_poly(const std::string& path, std::vector<std::string>* warnings = nullptr);

// read_node or read_poly, chosen by the extension (.node or .poly).
Pslg read_pslg(const std::string& path, std::vector<std::string>* warnings = nullptr);

// PREFIX.node + PREFIX.ele, plus PREFIX.poly (its segments become mesh.segments, with its
// holes and regions) and PREFIX.area (mesh.triangle_max_area) when those files exist.
// Every vertex counts as an input vertex (input_vertex_count = points.size()).
TriMesh read_mesh(const std::string& prefix, std::vector<std::string>* warnings = nullptr);

// The contents of a .edge file.
struct EdgeList {
  std::vector<Segment> edges;  // 0-based endpoints; marker 0 when the file has none
  bool has_markers = false;
};

// A .edge or .neigh file belonging to `mesh` (which fixes the numbering base and the
// valid index ranges). Not read by read_mesh: a stale file from an earlier run would be
// silently attached to the wrong mesh.
EdgeList read_edge(const std::string& path, const TriMesh& mesh,
                   std::vector<std::string>* warnings = nullptr);
// neighbors[t][i] as in TriMesh::neighbors (kNoIndex where the file says -1).
std::vector<std::array<std::uint32_t, 3>> read_neigh(const std::string& path,
                                                     const TriMesh& mesh,
                                                     std::vector<std::string>* warnings = nullptr);

struct WriteOptions {
  bool edges = false;      // also write PREFIX.edge
  bool neighbors = false;  // also write PREFIX.neigh
};

void write_node(const std::string& path, const TriMesh& mesh);
void write_ele(const std::string& path, const TriMesh& mesh);
// Vertex section empty ("0 2 0 1": the vertices are in the .node beside it), segments with
// markers, holes, regions.
void write_poly(const std::string& path, const TriMesh& mesh);
// Every edge of the triangulation once. Marker: the segment's marker when the edge is a
// segment with a nonzero marker, else 1 on boundary and constrained edges, else 0.
void write_edge(const std::string& path, const TriMesh& mesh);
// Uses mesh.neighbors, computing them when empty; -1 where there is no neighbour.
void write_neigh(const std::string& path, const TriMesh& mesh);
// mesh.triangle_max_area, one line per triangle.
void write_area(const std::string& path, const TriMesh& mesh);
// PREFIX.node, PREFIX.ele, PREFIX.poly; PREFIX.area when mesh.triangle_max_area is not
// empty; PREFIX.edge and PREFIX.neigh when asked for. Each file is replaced atomically on
// its own; an existing file that is not written (e.g. an old PREFIX.area) is left alone.
void write_mesh(const std::string& prefix, const TriMesh& mesh, const WriteOptions& = {});

// neighbors[t][i]: the triangle sharing the edge opposite triangles[t][i], kNoIndex when
// no triangle does (or when more than two triangles share that edge: not a manifold).
std::vector<std::array<std::uint32_t, 3>> compute_neighbors(const TriMesh& mesh);

}  // namespace meshstep::io
