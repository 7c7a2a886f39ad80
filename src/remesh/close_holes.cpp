#include "remesh/close_holes.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "geometry/hole_patch.hpp"
#include "remesh/output_defects.hpp"

namespace cvtmesh {

namespace {

// The boundary loops of `mesh` made wholly of opened edges (edges of `removed`), unless
// `every`; nothing when a vertex has two boundary edges leaving it (a non-manifold vertex:
// make_manifold leaves none).
std::optional<std::vector<HoleLoop>> opened_loops(const TriangleMesh& mesh,
                                                  const std::vector<EdgeUse>& uses,
                                                  std::span<const Triangle> removed, bool every) {
  std::vector<Edge> opened;
  for (const Triangle& t : removed)
    for (int k = 0; k < 3; ++k) opened.push_back(edge_of(t[k], t[(k + 1) % 3]));
  std::sort(opened.begin(), opened.end());
  std::optional<std::vector<HoleLoop>> loops = hole_loops(mesh, uses);
  if (!loops || every) return loops;
  std::erase_if(*loops, [&](const HoleLoop& loop) {
    return !std::all_of(loop.uses.begin(), loop.uses.end(), [&](std::size_t i) {
      return std::binary_search(opened.begin(), opened.end(), uses[i].edge);
    });
  });
  return loops;
}

}  // namespace

ClosedHoles close_opened_holes(TriangleMesh& mesh, std::span<const Triangle> removed,
                               const TopologyReport& input, bool oriented,
                               const std::function<Vec3(const Vec3&)>& onto_surface) {
  const std::vector<EdgeUse> uses = edge_uses(mesh);  // sorted by edge
  // A closed input's output has no hole of its own: every loop is one to close.
  const bool closed_input = input.is_closed();
  const std::optional<std::vector<HoleLoop>> loops =
      opened_loops(mesh, uses, removed, closed_input);
  if (!loops || loops->empty()) return {};
  const std::size_t before = mesh.triangles.size(), vertices_before = mesh.vertices.size();
  // Back to the first `triangles` and `vertices`, dropping what patches added after them.
  const auto truncate = [&](std::size_t triangles, std::size_t vertices) {
    mesh.triangles.resize(triangles);
    mesh.vertices.resize(vertices);
  };
  // A fan around a new vertex at the loop's centroid, onto the surface: it has no chord.
  const auto fan_of = [&](const HoleLoop& loop) {
    Vec3 centroid;
    for (const Index v : loop.vertices) centroid = centroid + mesh.vertices[v];
    const auto centre = static_cast<Index>(mesh.vertices.size());
    mesh.vertices.push_back(
        onto_surface((1.0 / static_cast<double>(loop.vertices.size())) * centroid));
    std::vector<Triangle> fan;
    for (std::size_t i = 0; i < loop.vertices.size(); ++i)
      fan.push_back({loop.vertices[i], loop.vertices[(i + 1) % loop.vertices.size()], centre});
    return fan;
  };
  // Each loop's patch, or nothing where CGAL finds no triangulation.
  const auto patch_of = [&](const HoleLoop& loop) -> std::optional<std::vector<Triangle>> {
    std::optional<std::vector<Triangle>> patch = hole_patch(mesh, loop);
    if (!patch) return std::nullopt;
    // A chord the mesh has already (the mesh as it came: the patches add none that another patch
    // could reuse, a chord joins two vertices of one loop, and no vertex is on two loops) would
    // make that edge non-manifold: then a fan closes the loop.
    if (reuses_edge(*patch, loop, uses)) return fan_of(loop);
    return patch;
  };
  // Whatever the patches made (a fold against a kept triangle, patches meeting at a vertex of
  // two loops), only a manifold is kept.
  const auto manifold = [&] {
    const std::vector<bool> may_bound(mesh.vertices.size(), true);
    return find_output_defects(mesh, may_bound, oriented).empty();
  };
  // A lone triangle (the removal cut it off) closes only with its own copy, which repair drops
  // again: a closed input's output loses it instead (below). Its loop is its own three edges,
  // so the triangle on the loop's first edge has the loop's third vertex.
  const auto lone = [](const HoleLoop& loop) {
    return loop.vertices.size() == 3 && loop.opposite[0] == loop.vertices[2];
  };
  const bool any_lone = std::any_of(loops->begin(), loops->end(), lone);
  // Adds the patches of `these` loops; whether each had one.
  const auto patch_all = [&](const auto& these) {
    bool all = true;
    for (const HoleLoop& loop : these) {
      const std::optional<std::vector<Triangle>> patch = patch_of(loop);
      if (patch) mesh.triangles.insert(mesh.triangles.end(), patch->begin(), patch->end());
      all = all && patch.has_value();
    }
    return all;
  };
  const bool all = patch_all(*loops);
  // A closed input's output must be closed too (issue 18: watertight, whatever else it lost):
  // there each hole closes whose patch leaves a manifold, even where the topology then differs
  // (a handle the removal cut through comes out capped, where it would otherwise be a tube
  // with two open ends). An open input's holes stay open: one may be its own boundary moved
  // inwards, which a patch would cap.
  if (all && manifold() &&
      ((closed_input && !any_lone) || same_topology(analyze_topology(mesh), input)))
    return {loops->size(), mesh.triangles.size() - before, mesh.vertices.size() - vertices_before};
  truncate(before, vertices_before);
  if (!closed_input) return {};
  ClosedHoles closed;
  std::vector<HoleLoop> open;
  std::vector<bool> dropped(mesh.triangles.size(), false);
  for (const HoleLoop& loop : *loops) {
    if (!lone(loop)) {
      open.push_back(loop);
      continue;
    }
    const Edge first = edge_of(loop.vertices[0], loop.vertices[1]);  // of one triangle: a boundary
    dropped[std::lower_bound(uses.begin(), uses.end(), first, [](const EdgeUse& u, const Edge& e) {
              return u.edge < e;
            })->triangle()] = true;
    ++closed.lone_triangles;
  }
  if (closed.lone_triangles > 0) {
    std::vector<Triangle> kept_triangles;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (!dropped[t]) kept_triangles.push_back(mesh.triangles[t]);
    mesh.triangles = std::move(kept_triangles);
  }
  // The other holes' patches at once, as that nearly always leaves a manifold (one check, not one
  // a hole: topology control tries this step on each round's output); else each hole its patch,
  // or else a fan, whichever first leaves a manifold. Without a lone triangle, the patches at
  // once were the first try already, and failed.
  const std::size_t kept = mesh.triangles.size();
  if (closed.lone_triangles > 0 && patch_all(open) && manifold()) {
    closed.holes = open.size();
    open.clear();
  } else {
    truncate(kept, vertices_before);
  }
  for (const HoleLoop& loop : open) {
    const std::size_t triangles = mesh.triangles.size(), vertices = mesh.vertices.size();
    const auto closes = [&](const std::optional<std::vector<Triangle>>& patch) {
      if (patch) mesh.triangles.insert(mesh.triangles.end(), patch->begin(), patch->end());
      if (patch && manifold()) return true;
      truncate(triangles, vertices);
      return false;
    };
    if (closes(patch_of(loop)) || closes(fan_of(loop))) ++closed.holes;
  }
  closed.triangles = mesh.triangles.size() + closed.lone_triangles - before;
  closed.vertices = mesh.vertices.size() - vertices_before;
  return closed;
}

}  // namespace cvtmesh
