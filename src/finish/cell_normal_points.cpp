#include "finish/cell_normal_points.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <optional>

#include "cvtmesh/rvd_consumers.hpp"
#include "features/edge_uses.hpp"
#include "finish/shape_floors.hpp"
#include "finish/undo_moves.hpp"
#include "geometry/shortest_edges.hpp"
#include "geometry/surface_projector.hpp"

namespace cvtmesh {

namespace {

// How far from the centroid the surface is looked for along the normal, in the vertex's
// shortest edges: past the sag of a chord of a tip or a ridge, short of the other side of a part
// thinner than an edge.
constexpr double kReach = 0.5;

}  // namespace

std::size_t move_onto_cell_normals(TriangleMesh& mesh, const std::vector<Vec3>& seeds,
                                   const std::vector<CellNormal>& cells,
                                   const SurfaceProjector& projector, std::vector<bool> movable) {
  const std::size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
  if (nt == 0) return 0;
  movable.resize(nv, false);
  const std::vector<bool> fixed = on_edges_not_of_two(mesh);
  for (std::size_t v = 0; v < nv; ++v) movable[v] = movable[v] && !fixed[v];
  std::map<Vec3, Index> seed_at;
  for (std::size_t s = 0; s < seeds.size(); ++s) seed_at.emplace(seeds[s], static_cast<Index>(s));
  std::vector<Index> seed_of(nv, kNoIndex);
  for (std::size_t v = 0; v < nv; ++v)
    if (const auto it = seed_at.find(mesh.vertices[v]); movable[v] && it != seed_at.end())
      seed_of[v] = it->second;
  const std::vector<double> shortest = shortest_edges(mesh);
  std::vector<std::optional<Vec3>> to(nv);
  tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t v) {
    if (seed_of[v] == kNoIndex) return;
    const CellNormal& cell = cells[seed_of[v]];
    if (cell.normal == Vec3{0, 0, 0}) return;
    if (const std::optional<double> t =
            projector.along(cell.centroid, cell.normal, kReach * shortest[v]))
      to[v] = cell.centroid + *t * cell.normal;
  });
  // Each triangle's floor and normal before the moves.
  const std::vector<MinShape> floor = shape_floors(mesh);
  const std::vector<Vec3> normal = unit_normals(mesh);
  const std::vector<Vec3> before = mesh.vertices;
  for (std::size_t v = 0; v < nv; ++v)
    if (to[v]) mesh.vertices[v] = *to[v];
  undo_moves_unless(mesh, before,
                    [&](std::size_t t) { return keeps_shape(mesh, t, floor[t], normal[t]); });
  std::size_t moved = 0;
  for (std::size_t v = 0; v < nv; ++v) moved += mesh.vertices[v] != before[v];
  return moved;
}

}  // namespace cvtmesh
