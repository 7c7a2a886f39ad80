#include "geometry/edge_splitter.hpp"

#include <algorithm>

#include "geometry/triangles_around.hpp"

namespace cvtmesh {

EdgeSplitter::EdgeSplitter(const TriangleMesh& mesh) : around_(triangles_around(mesh)) {}

void EdgeSplitter::split(TriangleMesh& mesh, Index p, Index q, Index x) {
  if (around_.size() < mesh.vertices.size()) around_.resize(mesh.vertices.size());
  const std::vector<Index> at_p = around_[p];  // copied: the loop changes the stars
  for (const Index i : at_p) {
    const Triangle t = mesh.triangles[i];
    for (int k = 0; k < 3; ++k) {
      const Index u = t[k], w = t[(k + 1) % 3], r = t[(k + 2) % 3];
      if (!((u == p && w == q) || (u == q && w == p))) continue;
      const auto j = static_cast<Index>(mesh.triangles.size());
      mesh.triangles[i] = {u, x, r};
      mesh.triangles.push_back({x, w, r});
      std::erase(around_[w], i);
      around_[w].push_back(j);
      around_[x].insert(around_[x].end(), {i, j});
      around_[r].push_back(j);
      break;
    }
  }
}

}  // namespace cvtmesh
