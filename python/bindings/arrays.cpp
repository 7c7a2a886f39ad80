#include "arrays.hpp"

#include <cmath>
#include <string>
#include <type_traits>

#include "cvtmesh/errors.hpp"

namespace cvtmesh::python {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_standard_layout_v<Vec3>);
static_assert(sizeof(Triangle) == 3 * sizeof(std::int32_t));
static_assert(sizeof(Edge) == 2 * sizeof(std::int32_t));

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// `object` as a C-contiguous (rows, columns) array of T; only integer input for integer T (a
// float index is a mistake, not something to round).
template <class T>
py::array_t<T, py::array::c_style> table(const py::handle& object, py::ssize_t columns,
                                         const char* name) {
  py::array any = py::array::ensure(object);
  if (!any) throw InputError(std::string(name) + ": not an array");
  const char kind = any.dtype().kind();
  const bool numeric = std::is_integral_v<T> ? (kind == 'i' || kind == 'u')
                                             : (kind == 'f' || kind == 'i' || kind == 'u');
  if (!numeric && any.size() > 0)
    throw InputError(std::string(name) + ": expected " +
                     (std::is_integral_v<T> ? "integers" : "numbers") + ", got dtype " +
                     std::string(py::str(any.dtype())));
  if (any.size() == 0)  // an empty list is a (0, k) table
    return py::array_t<T, py::array::c_style>(std::vector<py::ssize_t>{0, columns});
  if (any.ndim() != 2 || any.shape(1) != columns)
    throw InputError(std::string(name) + ": expected shape (n, " + std::to_string(columns) +
                     "), got " + shape_text(any));
  auto converted = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(any);
  if (!converted) throw py::error_already_set();  // numpy's own reason (an overflow, say)
  return converted;
}

// An array of T over `values`' buffer, which it keeps alive: (size) or (size, columns).
template <class T, class Stored>
py::array_t<T> owning_array(std::vector<Stored>&& values, py::ssize_t columns) {
  static_assert(std::is_trivially_copyable_v<Stored> && sizeof(Stored) % sizeof(T) == 0);
  auto* owner = new std::vector<Stored>(std::move(values));
  py::capsule release(owner, [](void* p) { delete static_cast<std::vector<Stored>*>(p); });
  const auto rows = static_cast<py::ssize_t>(owner->size());
  std::vector<py::ssize_t> shape{rows};
  if (columns > 0) shape.push_back(columns);
  return py::array_t<T>(shape, reinterpret_cast<const T*>(owner->data()), release);
}

}  // namespace

std::vector<Vec3> points_from_array(const py::handle& object, const char* name) {
  const auto a = table<double>(object, 3, name);
  const auto r = a.unchecked<2>();
  std::vector<Vec3> points(static_cast<std::size_t>(a.shape(0)));
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    points[i] = {r(i, 0), r(i, 1), r(i, 2)};
    if (!std::isfinite(r(i, 0)) || !std::isfinite(r(i, 1)) || !std::isfinite(r(i, 2)))
      throw InputError(std::string(name) + ": row " + std::to_string(i) +
                       " has a non-finite coordinate");
  }
  return points;
}

TriangleMesh mesh_from_arrays(const py::handle& vertices, const py::handle& triangles) {
  TriangleMesh mesh;
  mesh.vertices = points_from_array(vertices, "V");
  const auto f = table<std::int64_t>(triangles, 3, "F");
  const auto r = f.unchecked<2>();
  const auto n = static_cast<std::int64_t>(mesh.vertices.size());
  mesh.triangles.resize(static_cast<std::size_t>(f.shape(0)));
  for (py::ssize_t t = 0; t < f.shape(0); ++t)
    for (int c = 0; c < 3; ++c) {
      if (r(t, c) < 0 || r(t, c) >= n)
        throw InputError("F: row " + std::to_string(t) + " has vertex index " +
                         std::to_string(r(t, c)) + ", out of range (V has " + std::to_string(n) +
                         " rows)");
      mesh.triangles[t][c] = static_cast<Index>(r(t, c));
    }
  if (mesh.triangles.empty()) throw InputError("F: no triangles");
  return mesh;
}

std::vector<Edge> edges_from_array(const py::handle& object, std::size_t vertex_count) {
  const auto e = table<std::int64_t>(object, 2, "feature_edges");
  const auto r = e.unchecked<2>();
  std::vector<Edge> edges(static_cast<std::size_t>(e.shape(0)));
  for (py::ssize_t i = 0; i < e.shape(0); ++i) {
    for (int c = 0; c < 2; ++c)
      if (r(i, c) < 0 || r(i, c) >= static_cast<std::int64_t>(vertex_count))
        throw InputError("feature_edges: row " + std::to_string(i) + " has vertex id " +
                         std::to_string(r(i, c)) + ", out of range (V has " +
                         std::to_string(vertex_count) + " rows)");
    const auto a = static_cast<Index>(r(i, 0)), b = static_cast<Index>(r(i, 1));
    edges[i] = {std::min(a, b), std::max(a, b)};
  }
  return edges;
}

py::array_t<double> to_numpy(std::vector<Vec3>&& points) {
  return owning_array<double>(std::move(points), 3);
}
// Vertex ids stay below 2^31 (the library caps meshes at 50 million vertices): their bits read
// as int32, the index type numpy users expect.
py::array_t<std::int32_t> to_numpy(std::vector<Triangle>&& triangles) {
  return owning_array<std::int32_t>(std::move(triangles), 3);
}
py::array_t<std::int32_t> to_numpy(std::vector<Edge>&& edges) {
  return owning_array<std::int32_t>(std::move(edges), 2);
}
py::array_t<std::int32_t> to_numpy(std::vector<Index>&& ids) {
  return owning_array<std::int32_t>(std::move(ids), 0);
}
py::array_t<double> to_numpy(std::vector<double>&& values) {
  return owning_array<double>(std::move(values), 0);
}

py::object to_python(const nlohmann::ordered_json& j) {
  using Type = nlohmann::ordered_json::value_t;
  switch (j.type()) {
    case Type::null:
      return py::none();
    case Type::boolean:
      return py::bool_(j.get<bool>());
    case Type::number_integer:
      return py::int_(j.get<std::int64_t>());
    case Type::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case Type::number_float:
      return py::float_(j.get<double>());
    case Type::string:
      return py::str(j.get<std::string>());
    case Type::array: {
      py::list list;
      for (const auto& item : j) list.append(to_python(item));
      return list;
    }
    case Type::object: {
      py::dict dict;
      for (const auto& [key, value] : j.items()) dict[py::str(key)] = to_python(value);
      return dict;
    }
    default:
      return py::none();  // binary and discarded values never occur in reports
  }
}

}  // namespace cvtmesh::python
