// The `_meshstep` extension module. Every error of the core reaches Python as ValueError
// with the core's own message (InputError, RunSpecError); nothing the input can do crashes
// the interpreter.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "meshstep/error.hpp"
#include "meshstep/refine/run_spec.hpp"

PYBIND11_MODULE(_meshstep, m) {
  namespace py = pybind11;
  m.doc() = "meshstep's core, compiled; use the `meshstep` package, which documents it.";
  m.attr("__version__") = MESHSTEP_VERSION;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const meshstep::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const meshstep::RunSpecError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  meshstep::python::bind_triangulate(m);
  meshstep::python::bind_refine(m);
  meshstep::python::bind_log(m);
  meshstep::python::bind_terrain(m);
}
