// The `triangle` package's dictionaries: a PSLG (or a mesh to refine again) read from one,
// and a mesh written into one. Keys: vertices, vertex_markers, vertex_attributes,
// segments, segment_markers, holes, regions (x, y, attribute, max area), triangles,
// triangle_attributes, triangle_max_area, edges, edge_markers, neighbors. Indices from 0.
#pragma once

#include <pybind11/pybind11.h>

#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep::python {

namespace py = pybind11;

// A key that is there and not None.
bool has_key(const py::dict& tri, const char* key);

// The PSLG of tri (vertices required; segments, holes and regions only when `use_segments`,
// as Triangle reads them only with -p). Throws py::value_error naming the key.
Pslg pslg_from_dict(const py::dict& tri, bool use_segments);

// The mesh of tri for re-refinement (-r): the PSLG's parts and tri['triangles'], with
// tri['triangle_max_area'] when `areas`.
TriMesh mesh_from_dict(const py::dict& tri, bool areas);

struct DictOutput {
  bool edges = false, neighbors = false, triangle_attributes = false;
};

// The mesh as the triangle package returns it: (n, 1) markers and attributes columns, -1 for
// no neighbour.
py::dict mesh_to_dict(const TriMesh& mesh, const DictOutput& what);

// The edges of a mesh as `meshstep triangulate -e` writes them: each edge once, where it
// first occurs (lowest triangle, then lowest side) in that triangle's order; marker: the
// segment's when nonzero, else 1 on a segment or the boundary, else 0.
void mesh_edges(const TriMesh& mesh, std::vector<Segment>& edges);

}  // namespace meshstep::python
