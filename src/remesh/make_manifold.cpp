#include "remesh/make_manifold.hpp"

#include <algorithm>

#include "remesh/output_defects.hpp"

namespace cvtmesh {

std::vector<Triangle> make_manifold(TriangleMesh& mesh, bool oriented) {
  std::vector<Triangle> removed;
  // Boundary edges are allowed here: only what makes the mesh non-manifold goes, and folds when
  // the input is oriented (a non-orientable one, a Möbius strip, has a fold wherever it closes).
  const std::vector<bool> may_bound(mesh.vertices.size(), true);
  for (;;) {
    OutputDefects d = find_output_defects(mesh, may_bound, oriented);
    if (d.empty()) break;
    std::sort(d.triangles.begin(), d.triangles.end());
    const auto kept =
        std::stable_partition(mesh.triangles.begin(), mesh.triangles.end(), [&](const Triangle& t) {
          return !std::binary_search(d.triangles.begin(), d.triangles.end(), t);
        });
    removed.insert(removed.end(), kept, mesh.triangles.end());
    mesh.triangles.erase(kept, mesh.triangles.end());
  }
  return removed;
}

}  // namespace cvtmesh
