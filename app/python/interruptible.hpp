// Long runs without the GIL, stoppable by Ctrl+C.
//
// The core runs with the GIL released (other Python threads go on). Python's own SIGINT
// handler only sets a flag, which the interpreter looks at between bytecodes, so a run in
// C++ would not see it: the refinement's progress callback (about once a second) takes the
// GIL back for a moment and asks PyErr_CheckSignals, and a pending KeyboardInterrupt is
// thrown through the core as py::error_already_set, which pybind11 raises again in Python.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>

#include "meshstep/refine/refine.hpp"

namespace meshstep::python {

namespace py = pybind11;

// A progress callback for RefineOptions::progress that raises what a signal handler asks.
inline std::function<void(const RefineProgress&)> signal_checking_progress() {
  return [](const RefineProgress&) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
}

// Runs `work` with the GIL released; exceptions go through unchanged.
template <class Work>
auto without_gil(Work&& work) {
  py::gil_scoped_release release;
  return work();
}

}  // namespace meshstep::python
