// cvtmesh.read and cvtmesh.write: the CLI's readers and writers on numpy arrays.
#include <cerrno>
#include <filesystem>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "cvtmesh/io.hpp"

namespace cvtmesh::python {

namespace {

std::filesystem::path path_from(const py::object& path) {
  return py::module_::import("os").attr("fsdecode")(path).cast<std::string>();
}

py::tuple read(const py::object& path_object) {
  const std::filesystem::path path = path_from(path_object);
  std::error_code error;
  // A file that is not there, or is not a file, is an OSError; what a file holds, a ValueError.
  if (!std::filesystem::exists(path, error)) {
    PyErr_SetObject(PyExc_FileNotFoundError,
                    py::make_tuple(ENOENT, "No such file", path.string()).ptr());
    throw py::error_already_set();
  }
  if (std::filesystem::is_directory(path, error)) {
    PyErr_SetObject(PyExc_IsADirectoryError,
                    py::make_tuple(EISDIR, "Is a directory", path.string()).ptr());
    throw py::error_already_set();
  }
  TriangleMesh mesh;
  {
    py::gil_scoped_release released;
    mesh = read_mesh(path);
  }
  return py::make_tuple(to_numpy(std::move(mesh.vertices)), to_numpy(std::move(mesh.triangles)));
}

void write(const py::object& path, const py::object& V, const py::object& F) {
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  const std::filesystem::path target = path_from(path);
  py::gil_scoped_release released;
  write_mesh(target, mesh);
}

}  // namespace

void add_io(py::module_& m) {
  m.def("read", &read, py::arg("path"), R"(Read a triangle mesh: OBJ, OFF, PLY or STL.

Returns (V, F): (n, 3) float64 vertex coordinates and (m, 3) int32 triangles, as stored
(polygons are fan-triangulated; nothing is repaired). Raises FileNotFoundError for a missing
file, OSError for one that cannot be read, ValueError for malformed or unusable content
(non-finite coordinates, out-of-range indices, no triangles), naming the file.)");
  m.def("write", &write, py::arg("path"), py::arg("V"), py::arg("F"),
        R"(Write a triangle mesh; the format is chosen by the extension.

OBJ and OFF are ASCII (round-trip precision), PLY binary little-endian, STL binary. The file
appears atomically (written under a temporary name, then renamed). Raises OSError when it
cannot be written, ValueError for an unknown extension or bad arrays.)");
}

}  // namespace cvtmesh::python
