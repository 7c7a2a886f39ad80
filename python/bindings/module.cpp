// The compiled part of the `cvtmesh` Python package (cvtmesh/_cvtmesh): the library on numpy
// arrays. The package's __init__.py re-exports it.
#include "bindings.hpp"
#include "cvtmesh/version.hpp"

PYBIND11_MODULE(_cvtmesh, m) {
  m.doc() = "cvtmesh: isotropic surface remeshing by centroidal Voronoi tessellation";
  m.attr("__version__") = cvtmesh::version();
  cvtmesh::python::add_errors(m);
  cvtmesh::python::add_io(m);
  cvtmesh::python::add_measures(m);
  cvtmesh::python::add_remesh(m);
}
