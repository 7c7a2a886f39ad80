// The parts of the `cvtmesh` Python module, each adding its functions to it.
#pragma once

#include <pybind11/pybind11.h>

namespace cvtmesh::python {

namespace py = pybind11;

void add_errors(py::module_& m);
void add_io(py::module_& m);
void add_measures(py::module_& m);
void add_remesh(py::module_& m);

}  // namespace cvtmesh::python
