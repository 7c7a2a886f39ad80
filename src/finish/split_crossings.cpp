#include "finish/split_crossings.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include "features/edge_uses.hpp"
#include "finish/changed_vertices.hpp"
#include "finish/improve_shapes.hpp"
#include "geometry/self_crossings.hpp"
#include "geometry/surface_projector.hpp"
#include "geometry/unit_vector.hpp"

namespace cvtmesh {

namespace {

// Rounds in a row without fewer crossing triangles, after which the halving stops: where the
// triangles that cross span a plate, each round's halves cross as their triangle did.
constexpr int kRoundsWithoutFewer = 3;
// The sweeps' cap around the new vertices, as the finishing steps' default.
constexpr int kSweeps = 5;

// One round of split_crossings' halvings on `mesh`, `crossing` its crossing triangles. Returns
// how many edges it halved.
std::size_t halve_crossing_edges(TriangleMesh& mesh, const std::vector<Triangle>& crossing,
                                 const std::vector<Edge>& features,
                                 const SurfaceProjector& surface) {
  const std::set<Triangle> crossing_set(crossing.begin(), crossing.end());
  const std::size_t triangles = mesh.triangles.size();
  std::vector<bool> crosses(triangles, false);
  for (std::size_t t = 0; t < triangles; ++t) crosses[t] = crossing_set.contains(mesh.triangles[t]);
  // Per crossing triangle, its longest edge that may be halved: the uses of that edge, its own
  // and the other triangle's.
  struct Pick {
    double length = -1;
    std::size_t mine = 0, theirs = 0;
  };
  std::vector<Pick> pick(triangles);
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j - i != 2) return;
    const Edge& e = uses[i].edge;
    const std::size_t t = uses[i].triangle(), u = uses[i + 1].triangle();
    if (t == u || !(crosses[t] || crosses[u]) ||
        std::binary_search(features.begin(), features.end(), e) ||
        runs_forward(mesh.triangles[t], e[0], e[1]) == runs_forward(mesh.triangles[u], e[0], e[1]))
      return;
    const double length = distance(mesh.vertices[e[0]], mesh.vertices[e[1]]);
    if (crosses[t] && length > pick[t].length) pick[t] = {length, i, i + 1};
    if (crosses[u] && length > pick[u].length) pick[u] = {length, i + 1, i};
  });
  std::vector<bool> split(triangles, false);
  std::size_t halved = 0;
  for (std::size_t x = 0; x < triangles; ++x) {
    if (pick[x].length < 0) continue;
    const EdgeUse &mine = uses[pick[x].mine], &theirs = uses[pick[x].theirs];
    const std::size_t t = mine.triangle(), u = theirs.triangle();
    if (split[t] || split[u]) continue;
    // t = (a, b, c) runs a -> b, u = (b, a, d) back.
    const Triangle ft = mesh.triangles[t], fu = mesh.triangles[u];
    const std::size_t k = mine.corner % 3, l = theirs.corner % 3;
    const Index a = ft[k], b = ft[(k + 1) % 3], c = ft[(k + 2) % 3], d = fu[(l + 2) % 3];
    const Vec3 &pa = mesh.vertices[a], &pb = mesh.vertices[b];
    const Vec3 normal =
        unit_or_zero(unit_normal(pa, pb, mesh.vertices[c]) + unit_normal(pb, pa, mesh.vertices[d]));
    const Vec3 middle = 0.5 * (pa + pb);
    // On the sheet the triangles face the way of, not the nearest: beside a thin wall that is the
    // wall's other side. (The output faces as the input does: each triangle of the restricted
    // Delaunay triangulation is oriented like the facet it is dual to.) The ends' nearest sheets
    // do not tell: an end may stand nearer the other side (couplingdown.off at 100).
    const std::optional<double> along =
        surface.along(middle, normal, 0.5 * distance(pa, pb), normal);
    if (!along) continue;
    halve_edge(mesh, t, u, a, b, c, d, middle + *along * normal);
    split[t] = split[u] = true;
    ++halved;
  }
  return halved;
}

}  // namespace

std::size_t split_crossings(RemeshResult& result, const SurfaceProjector& surface,
                            InputCrossings& input, int rounds) {
  std::vector<Triangle> crossing = crossings_of_its_own(result.mesh, input);
  const std::size_t before = crossing.size();
  std::size_t fewest = before;
  TriangleMesh best, mesh = result.mesh;
  for (int round = 0, without = 0; round < rounds && fewest > 0 && without < kRoundsWithoutFewer;
       ++round) {
    if (halve_crossing_edges(mesh, crossing, result.feature_edges, surface) == 0) break;
    crossing = crossings_of_its_own(mesh, input);
    if (crossing.size() < fewest) {
      fewest = crossing.size();
      best = mesh;
      without = 0;
    } else {
      ++without;
    }
  }
  if (fewest == before) return 0;
  // The sweeps around the new vertices: corners of feature edges held, every change there checked
  // for crossings; kept where they leave no more than the halvings did.
  const std::size_t first_new = result.mesh.vertices.size();
  const std::vector<bool> active = around_new_vertices(best, first_new);
  std::vector<VertexSupport> supports(best.vertices.size());
  for (std::size_t v = 0; v < supports.size(); ++v) supports[v].guarded = active[v];
  for (const Edge& e : result.feature_edges)
    for (const Index v : e) supports[v].kind = VertexSupport::Kind::fixed;
  TriangleMesh swept = best;
  std::vector<Edge> features = result.feature_edges;
  improve_shapes(swept, surface, nullptr, std::move(supports), features, kSweeps, {}, active);
  if (const std::size_t left = crossings_of_its_own(swept, input).size(); left <= fewest) {
    best = std::move(swept);
    result.feature_edges = std::move(features);
    fewest = left;
  }
  result.mesh = std::move(best);
  result.output_crossing_triangles = fewest;
  // A collapse in the sweeps leaves its vertex unused.
  std::vector<bool> unused_flags(result.mesh.vertices.size(), false);
  drop_unused_vertices(result, unused_flags);
  const std::size_t now = result.mesh.vertices.size();
  return now > first_new ? now - first_new : 0;
}

}  // namespace cvtmesh
