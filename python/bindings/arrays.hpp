// numpy arrays <-> cvtmesh's meshes and point lists. Inputs are checked (shape, dtype, finite
// coordinates, indices in range) and copied once into the library's types; outputs are handed to
// numpy without a copy (the array owns the vector's buffer).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh::python {

namespace py = pybind11;

// `vertices`: (n, 3) floats; `triangles`: (m, 3) integers in [0, n). InputError (ValueError),
// naming the argument, for anything else.
TriangleMesh mesh_from_arrays(const py::handle& vertices, const py::handle& triangles);
// (n, 3) floats, finite; `name` names the argument in errors.
std::vector<Vec3> points_from_array(const py::handle& points, const char* name);
// (k, 2) integers: edges of vertex ids (any order within a row), each < vertex_count.
std::vector<Edge> edges_from_array(const py::handle& edges, std::size_t vertex_count);

// (n, 3) float64 and (m, 3) int32 arrays that take over the vectors' buffers.
py::array_t<double> to_numpy(std::vector<Vec3>&& points);
py::array_t<std::int32_t> to_numpy(std::vector<Triangle>&& triangles);
py::array_t<std::int32_t> to_numpy(std::vector<Edge>&& edges);
py::array_t<std::int32_t> to_numpy(std::vector<Index>&& ids);
py::array_t<double> to_numpy(std::vector<double>&& values);

// A JSON report as Python objects: dict (in the report's key order), list, str, int, float,
// bool, None.
py::object to_python(const nlohmann::ordered_json& json);

}  // namespace cvtmesh::python
