// Triangle surfaces in 3D: reading and writing OFF, OBJ, PLY and STL files, and a report of
// what keeps a surface from being a clean 2-manifold.
//
// Reading is strict, as for Triangle's files: every problem is an InputError whose what()
// reads "FILE:LINE: message" for the text formats (the line of the bad token), and
// "FILE: byte offset N: message" for the binary ones. Counts are checked against the file's
// size before anything is reserved, so a hostile file cannot make a reader allocate more
// than a small multiple of its own size.
//
// Polygons with more than 3 vertices (OFF, OBJ, PLY) become fans of triangles around their
// first vertex: exact for the convex polygons exporters write, and it keeps the file's
// orientation.
//
// Writers replace the target atomically (a temporary file renamed into place) and refuse a
// surface they cannot write faithfully (an index past the end, a coordinate that is not
// finite) before touching it. The text formats and binary PLY (doubles) give back exactly
// the same doubles; binary STL stores float32, so its coordinates are rounded to float.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "meshstep/geometry/point3.hpp"

namespace meshstep::io {

using meshstep::Point3;

struct Surface {
  std::vector<Point3> vertices;
  // Indices into vertices, counterclockwise seen from outside.
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

enum class SurfaceFormat { off, obj, ply_ascii, ply_binary, stl_ascii, stl_binary };

// The format named by the path's extension (.off .obj .ply .stl, in any case); nullopt for
// any other. PLY and STL exist in both kinds: binary unless `ascii` (which only matters
// for writing: read_surface tells them apart by their content).
std::optional<SurfaceFormat> surface_format_for(const std::string& path, bool ascii = false);

// Reads a surface, its format chosen by the extension. PLY files say in their header
// whether they are ASCII or binary (either byte order); an STL file is binary when its
// size is exactly what its triangle count says (80-byte header, count, 50 bytes a
// triangle), else ASCII when it starts with "solid". STL repeats each vertex in every
// triangle: exactly equal coordinates are welded into one vertex, numbered in order of
// first appearance. OBJ: only `v` and `f` records are used; texture and normal indices
// (f v/vt/vn) and every other record are ignored.
Surface read_surface(const std::string& path);

// Writes `s` as `f`, whatever the path's extension says.
void write_surface(const std::string& path, const Surface& s, SurfaceFormat f);

// What is not a clean 2-manifold surface. Triangles with a repeated vertex take no part in
// the edge counts; every other triangle (duplicates and zero-area ones included) does.
struct SurfaceReport {
  std::size_t degenerate_triangles = 0;  // a repeated vertex, or exactly collinear corners
  std::size_t duplicate_triangles = 0;   // same three vertices as an earlier one, any order
  std::size_t non_manifold_edges = 0;    // edges used by more than two triangles
  std::size_t inconsistent_edges = 0;    // edges used twice in the same direction
  std::size_t boundary_loops = 0;        // closed chains of boundary edges (holes, borders)
  std::size_t boundary_edges = 0;        // edges used by one triangle
  std::size_t unused_vertices = 0;       // vertices of no triangle

  // Nothing wrong but, possibly, a boundary: a surface with a border is still clean.
  bool clean() const;
};

// Throws InputError when a triangle refers to a vertex past the end.
SurfaceReport report_surface(const Surface& s);

// One line for people, e.g. "not clean: 1 duplicate triangle; 1 boundary loop (4 edges)".
std::string describe(const SurfaceReport& r);

}  // namespace meshstep::io
