#include "finish/cell_normal_points.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <optional>

#include "features/edge_uses.hpp"
#include "finish/move_limits.hpp"
#include "finish/undo_moves.hpp"
#include "geometry/shortest_edges.hpp"
#include "geometry/surface_projector.hpp"
#include "geometry/unit_vector.hpp"
#include "quality/min_shape.hpp"

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
  // Each triangle's floors and normal before the moves: its own shape, or the aim where it is
  // better, and never under the mesh's worst (θmin and Qmin do not fall).
  std::vector<MinShape> floor(nt);
  std::vector<Vec3> normal(nt);
  MinShape worst{1, 180};
  for (std::size_t t = 0; t < nt; ++t) {
    const auto [a, b, c] = mesh.corners(t);
    floor[t] = min_shape(a, b, c);
    worst = {std::min(worst.quality, floor[t].quality),
             std::min(worst.min_angle, floor[t].min_angle)};
    normal[t] = unit_normal(a, b, c);
  }
  const MinShape aim{std::max(kAimQuality, worst.quality), std::max(kAimAngleDeg, worst.min_angle)};
  for (MinShape& f : floor)
    f = {std::min(f.quality, aim.quality), std::min(f.min_angle, aim.min_angle)};
  const std::vector<Vec3> before = mesh.vertices;
  for (std::size_t v = 0; v < nv; ++v)
    if (to[v]) mesh.vertices[v] = *to[v];
  undo_moves_unless(mesh, before, [&](std::size_t t) {
    const auto [a, b, c] = mesh.corners(t);
    const MinShape s = min_shape(a, b, c);
    return s.min_angle >= floor[t].min_angle && s.quality >= floor[t].quality &&
           dot(unit_normal(a, b, c), normal[t]) >= kMaxShiftTurnCos;
  });
  std::size_t moved = 0;
  for (std::size_t v = 0; v < nv; ++v) moved += mesh.vertices[v] != before[v];
  return moved;
}

}  // namespace cvtmesh
