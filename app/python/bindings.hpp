// The parts of the `_meshstep` extension, each in its own file, added by module.cpp.
#pragma once

#include <pybind11/pybind11.h>

namespace meshstep::python {

namespace py = pybind11;

void bind_triangulate(py::module_& m);  // triangulate (the triangle package's dicts), read_poly
void bind_refine(py::module_& m);       // refine (the run description, numpy arrays)
void bind_log(py::module_& m);          // replay logs
void bind_terrain(py::module_& m);      // terrain tiles, for terrain_tiles on a Dask cluster

}  // namespace meshstep::python
