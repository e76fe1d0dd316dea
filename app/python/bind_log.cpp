#include "bindings.hpp"
namespace meshstep::python {
void bind_log(py::module_&) {}
}
