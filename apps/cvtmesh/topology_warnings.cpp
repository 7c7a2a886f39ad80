#include "topology_warnings.hpp"

#include <fmt/core.h>

namespace cvtmesh::cli {

void warn_about_topology(const std::string& file, const TopologyReport& t) {
  if (t.nonmanifold_edges > 0)
    fmt::print(stderr, "{}: warning: {} non-manifold edges (three or more triangles)\n", file,
               t.nonmanifold_edges);
  if (t.nonmanifold_vertices > 0)
    fmt::print(stderr, "{}: warning: {} non-manifold vertices\n", file, t.nonmanifold_vertices);
  if (t.components > 1)
    fmt::print(stderr, "{}: note: {} connected components\n", file, t.components);
  if (!t.orientable) fmt::print(stderr, "{}: note: the surface is not orientable\n", file);
}

}  // namespace cvtmesh::cli
