#include "finish/changed_vertices.hpp"

#include <algorithm>

#include "cvtmesh/repair.hpp"

namespace cvtmesh {

std::vector<bool> around_new_vertices(const TriangleMesh& mesh, std::size_t first_new) {
  std::vector<bool> near(mesh.vertices.size(), false);
  std::fill(near.begin() + static_cast<std::ptrdiff_t>(first_new), near.end(), true);
  for (int ring = 0; ring < 2; ++ring) {
    std::vector<bool> grown = near;
    for (const Triangle& t : mesh.triangles)
      if (near[t[0]] || near[t[1]] || near[t[2]]) grown[t[0]] = grown[t[1]] = grown[t[2]] = true;
    near = std::move(grown);
  }
  return near;
}

Index halve_edge(TriangleMesh& mesh, std::size_t t, std::size_t u, Index a, Index b, Index c,
                 Index d, const Vec3& point) {
  const auto m = static_cast<Index>(mesh.vertices.size());
  mesh.vertices.push_back(point);
  mesh.triangles[t] = {c, a, m};
  mesh.triangles.push_back({c, m, b});
  if (d != kNoIndex) {
    mesh.triangles[u] = {b, m, d};
    mesh.triangles.push_back({m, a, d});
  }
  return m;
}

void drop_unused_vertices(RemeshResult& r, std::vector<bool>& flags) {
  std::vector<Index> new_id;
  repair_mesh(r.mesh, &new_id);
  std::erase_if(r.vertices_added, [&](Index v) { return new_id[v] == kRemovedVertex; });
  for (Index& v : r.vertices_added) v = new_id[v];
  r.feature_edges = edges_after_repair(r.feature_edges, new_id);
  std::vector<bool> kept(r.mesh.vertices.size(), false);
  for (std::size_t v = 0; v < new_id.size(); ++v)
    if (new_id[v] != kRemovedVertex) kept[new_id[v]] = flags[v];
  flags = std::move(kept);
}

}  // namespace cvtmesh
