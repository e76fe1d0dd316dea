// A 2D mesh written whole into one file of another program's format, for `-o OUT.EXT`
// (the table in formats.hpp says which extension goes where). Triangle's own files, with
// every detail of the mesh, stay the default (triangle_io.hpp: write_mesh).
//
// Every writer checks what it writes (indices in range, finite coordinates) before it
// touches the target, and replaces the target atomically (a temporary file beside it,
// renamed into place): a failure leaves no half-written file. Coordinates are written in
// their shortest exact form, except binary STL's float32. Problems are
// InputError("PATH: cannot write this mesh: ...").
#pragma once

#include <string>

#include "meshstep/io/surface_io.hpp"
#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep::io {

// gmsh's MSH 4.1, ASCII. Nodes 1..N are the mesh's vertices in order (unused ones too);
// triangles are elements of type 2, one surface entity per region attribute; segments are
// elements of type 1, one curve entity per segment marker. Each entity is its own physical
// group, named "region ATTRIBUTE" or "marker M" in $PhysicalNames.
void write_gmsh(const std::string& path, const TriMesh& mesh);

// VTK's XML UnstructuredGrid (.vtu), its arrays binary (appended raw data). Triangles are cells of type 5 (VTK_TRIANGLE);
// cell data: region (the attribute, 0 without one), min_angle (degrees) and quality (min
// angle / 60: 1 for an equilateral triangle); point data: marker (0 without markers).
void write_vtu(const std::string& path, const TriMesh& mesh);

// The mesh as a surface in the plane z = 0 (orientation kept: counterclockwise seen from +z).
Surface planar_surface(const TriMesh& mesh);

// The surface writers (surface_io.hpp) on planar_surface(mesh): triangles only.
void write_mesh_off(const std::string& path, const TriMesh& mesh);
void write_mesh_obj(const std::string& path, const TriMesh& mesh);
void write_mesh_ply(const std::string& path, const TriMesh& mesh);  // binary, doubles
void write_mesh_stl(const std::string& path, const TriMesh& mesh);  // binary, float32

}  // namespace meshstep::io
