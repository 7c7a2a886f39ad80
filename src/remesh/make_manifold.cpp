#include "remesh/make_manifold.hpp"

#include <algorithm>

#include "geometry/manifold_defects.hpp"

namespace cvtmesh {

namespace {

// Takes the flagged triangles out of `mesh` (keeping the others' order) into `removed`; returns
// the vertices of those taken.
std::vector<bool> remove_flagged(TriangleMesh& mesh, std::vector<Triangle> flagged,
                                 std::vector<Triangle>& removed) {
  std::sort(flagged.begin(), flagged.end());
  const auto kept = std::stable_partition(
      mesh.triangles.begin(), mesh.triangles.end(),
      [&](const Triangle& t) { return !std::binary_search(flagged.begin(), flagged.end(), t); });
  std::vector<bool> touched(mesh.vertices.size(), false);
  for (auto t = kept; t != mesh.triangles.end(); ++t)
    for (const Index v : *t) touched[v] = true;
  removed.insert(removed.end(), kept, mesh.triangles.end());
  mesh.triangles.erase(kept, mesh.triangles.end());
  return touched;
}

}  // namespace

std::vector<Triangle> make_manifold(TriangleMesh& mesh, bool oriented) {
  std::vector<Triangle> removed;
  // Boundary edges are allowed here: only what makes the mesh non-manifold goes, and folds when
  // the input is oriented (a non-orientable one, a Möbius strip, has a fold wherever it closes).
  const std::vector<bool> may_bound(mesh.vertices.size(), true);
  // Taking triangles away makes no edge non-manifold or folded; it can only split the fan of a
  // vertex they had. So the first pass looks at the whole mesh, and each one after it at the
  // triangles around the vertices of those just taken, for several fans there only (may_branch
  // silences the others, whose fans these triangles show in part): the same triangles as a pass
  // over the whole mesh, without sorting all its edges again (femur.off at 10k: 4 to 6 passes
  // per last step, and a last step per round of topology control).
  std::vector<bool> touched(mesh.vertices.size(), true);
  for (;;) {
    std::vector<Triangle> around;
    for (const Triangle& t : mesh.triangles)
      if (touched[t[0]] || touched[t[1]] || touched[t[2]]) around.push_back(t);
    std::vector<bool> elsewhere = touched;
    elsewhere.flip();
    const ManifoldDefects d =
        find_manifold_defects(mesh.vertices.size(), around, may_bound, oriented, elsewhere);
    std::vector<Triangle> found;
    for (std::size_t t = 0; t < around.size(); ++t)
      if (d.triangle[t]) found.push_back(around[t]);
    if (found.empty()) return removed;
    touched = remove_flagged(mesh, std::move(found), removed);
  }
}

}  // namespace cvtmesh
