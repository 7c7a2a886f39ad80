#include "cvt/polish_defects.hpp"

#include <algorithm>
#include <functional>
#include <iterator>
#include <map>

#include "cvt/triangle_pieces.hpp"
#include "geometry/even_spacing.hpp"
#include "geometry/point_tree.hpp"
#include "quality/min_shape.hpp"
#include "voronoi/multi_nerve.hpp"
#include "voronoi/polygon_reach.hpp"

namespace cvtmesh {

namespace {

// A triangle is defective below what a converged CVT gives on smooth surfaces (θmin about 35-38°,
// Qmin about 0.65, as geogram's vorpalite reaches too): well above the usual quality bar of
// θmin 30°, Q 0.6. Where Lloyd cannot reach it (next to feature corners), the rounds stop.
constexpr double kMinAngleDeg = 35;
constexpr double kMinQuality = 0.65;
// How far from PolishSettings::around a defect is still polished, in rings of triangles.
constexpr int kAroundRings = 4;

// Whether the triangle has a defective shape.
bool defective(const TriangleMesh& mesh, const Triangle& t) {
  const MinShape shape = min_shape(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
  return shape.min_angle < kMinAngleDeg || shape.quality < kMinQuality;
}

// The seeds of the defective triangles that are not `settled`, sorted; `count` is set to the
// number of all defective triangles.
template <class Settled>
std::vector<Index> defective_seeds(const TriangleMesh& rdt, const Settled& settled,
                                   std::size_t& count) {
  std::vector<Index> seeds;
  count = 0;
  for (const Triangle& t : rdt.triangles) {
    if (!defective(rdt, t)) continue;
    ++count;
    if (!settled(t)) seeds.insert(seeds.end(), t.begin(), t.end());
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  return seeds;
}

// `set` (sorted) and its neighbours in the triangulation, sorted.
std::vector<Index> grown(const std::vector<Index>& set, const TriangleMesh& rdt) {
  std::vector<Index> out = set;
  for (const Triangle& t : rdt.triangles)
    if (std::any_of(t.begin(), t.end(),
                    [&](Index v) { return std::binary_search(set.begin(), set.end(), v); }))
      out.insert(out.end(), t.begin(), t.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The triangles of `mesh` whose vertices are all below `n`, with all its vertices.
TriangleMesh among_seeds(const TriangleMesh& mesh, std::size_t n) {
  TriangleMesh out;
  out.vertices = mesh.vertices;
  for (const Triangle& t : mesh.triangles)
    if (t[0] < n && t[1] < n && t[2] < n) out.triangles.push_back(t);
  return out;
}

// Input triangles as a mesh of their own, with the density at its vertices (empty for ρ = 1).
struct Patch {
  TriangleMesh mesh;
  std::vector<double> density;
};

// The input triangles `ids` as a patch; of those that `pieces` cuts, the pieces that `balls`
// there reach (CellCoverage::balls_of). `rho`: the density per vertex of `surface`, or null.
Patch sub_surface(const TriangleMesh& surface, const std::vector<Index>& ids,
                  const std::vector<double>* rho, const TrianglePieces& pieces,
                  const std::map<Index, std::vector<Ball>>& balls) {
  Patch sub;
  std::vector<Index> renumbered(surface.vertices.size(), kNoIndex);
  for (Index t : ids) {
    if (pieces.cut(t)) {
      pieces.add_pieces(t, balls.at(t), rho, sub.mesh, sub.density);
      continue;
    }
    Triangle f = surface.triangles[t];
    for (Index& v : f) {
      if (renumbered[v] == kNoIndex) {
        renumbered[v] = static_cast<Index>(sub.mesh.vertices.size());
        sub.mesh.vertices.push_back(surface.vertices[v]);
        if (rho) sub.density.push_back((*rho)[v]);
      }
      v = renumbered[v];
    }
    sub.mesh.triangles.push_back(f);
  }
  return sub;
}

// The polygon corners of the cells of some seeds (by their index in the RVD's seed list).
class CellCorners : public PolygonSink {
 public:
  explicit CellCorners(std::function<bool(Index)> wanted) : wanted_(std::move(wanted)) {}
  void begin(std::size_t chunks) override { chunks_.assign(chunks, {}); }
  void polygon(std::size_t chunk, const RvdPolygon& p) override {
    if (!wanted_(p.seed)) return;
    for (const RvdVertex& v : p.vertices) chunks_[chunk].push_back({p.seed, v.point});
  }
  // Per chunk, in order: (seed, corner) pairs.
  const std::vector<std::vector<std::pair<Index, Vec3>>>& chunks() const { return chunks_; }

 private:
  std::function<bool(Index)> wanted_;
  std::vector<std::vector<std::pair<Index, Vec3>>> chunks_;
};

// The seeds not in `local` (sorted) that are nearer to a corner of a local cell than that cell's
// seed (at `positions`): the local RVD gave the cell a part that is theirs. `tree` holds all the
// seeds at `fixed`, their positions before this round's steps (only local seeds move). Such a
// seed is within twice the cell's reach of its seed: one search per cell, not per corner
// (femur.off at 5k, whose topology control polishes around hundreds of new seeds: 8.8 → 8.4 s).
std::vector<Index> intruders(const CellCorners& corners, const std::vector<Index>& local,
                             const std::vector<Vec3>& positions, const PointTree& tree,
                             const std::vector<Vec3>& fixed) {
  // Per local cell, its corners and their squared distances to its seed.
  std::vector<std::vector<std::pair<Vec3, double>>> of_cell(local.size());
  for (const auto& chunk : corners.chunks())
    for (const auto& [k, corner] : chunk)
      of_cell[k].emplace_back(corner, dot(corner - positions[k], corner - positions[k]));
  std::vector<Index> out, near;
  for (std::size_t k = 0; k < local.size(); ++k) {
    if (of_cell[k].empty()) continue;
    double reach2 = 0;
    for (const auto& [corner, r2] : of_cell[k]) reach2 = std::max(reach2, r2);
    tree.within(positions[k], 4 * reach2 * (1 + 1e-6), near);
    for (const Index s : near) {
      if (std::binary_search(local.begin(), local.end(), s)) continue;
      if (std::any_of(of_cell[k].begin(), of_cell[k].end(), [&](const auto& corner_r2) {
            const Vec3 to = fixed[s] - corner_r2.first;
            return dot(to, to) < corner_r2.second;
          }))
        out.push_back(s);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Lloyd steps on the seeds `moving`: each goes to its cell's centroid, under its constraint,
// until the triangles among them have no defect, or after `steps` steps. The cells are
// computed over `patch` (the input triangles around them) among the seeds `local` (the moving
// seeds and enough rings around them to shape those cells), which also gives their triangles.
// An input triangle far larger than a cell (a CAD facet) reaches beyond those rings: the local
// RVD would give its far parts to the nearest local cell, whose centroid would then pull its
// seed many cells away. So any seed nearer to a corner of a moving cell joins `local`, and the
// step is computed again, until the moving cells are exact.
// `density`: ρ per vertex of the patch, empty for ρ = 1.
void local_lloyd(const TriangleMesh& patch, const std::vector<double>& density,
                 std::vector<Index> local, const std::vector<Index>& moving,
                 std::vector<Vec3>& seeds, const CvtObjective& objective, int steps,
                 const PointTree& tree, const std::vector<Vec3>& fixed) {
  const auto is_moving = [&](Index k) {
    return std::binary_search(moving.begin(), moving.end(), local[k]);
  };
  std::vector<Vec3> positions;
  // A step moves the seeds a little: their neighbour lists carry over (while `local` keeps its
  // size), as between the optimizer's evaluations.
  NeighborCache neighbors;
  for (int step = 0; step < steps; ++step) {
    positions.resize(local.size());
    for (std::size_t k = 0; k < local.size(); ++k) positions[k] = seeds[local[k]];
    const RestrictedVoronoiDiagram rvd(patch, positions, neighbors);
    CellIntegrator integrator(rvd, density);
    RestrictedDelaunayBuilder rdt(rvd);
    CellCorners corners(is_moving);
    PolygonSink* sinks[] = {&integrator, &rdt, &corners};
    rvd.traverse(sinks);
    if (const std::vector<Index> more = intruders(corners, local, positions, tree, fixed);
        !more.empty()) {
      std::vector<Index> joined;
      std::set_union(local.begin(), local.end(), more.begin(), more.end(),
                     std::back_inserter(joined));
      local = std::move(joined);
      --step;  // this step again, with them
      continue;
    }
    const TriangleMesh& around = rdt.result();
    if (std::none_of(around.triangles.begin(), around.triangles.end(), [&](const Triangle& t) {
          return std::all_of(t.begin(), t.end(), is_moving) && defective(around, t);
        }))
      return;
    const CellIntegrals& cells = integrator.result();
    std::vector<Vec3> taken = positions;
    std::sort(taken.begin(), taken.end());
    for (std::size_t k = 0; k < local.size(); ++k) {
      if (cells.mass[k] <= 0 || !is_moving(static_cast<Index>(k))) continue;
      const Vec3 to = objective.constrained(local[k], cells.centroid(static_cast<Index>(k)));
      // Seeds stay distinct: a move onto a point already taken (a convex corner, say) waits.
      if (std::binary_search(taken.begin(), taken.end(), to)) continue;
      taken.insert(std::upper_bound(taken.begin(), taken.end(), to), to);
      seeds[local[k]] = to;
    }
  }
}

}  // namespace

PolishedOutput extract_polished(const TriangleMesh& surface, std::vector<Vec3>& seeds,
                                const CvtObjective& objective, const PolishSettings& settings,
                                ExtractionMemory& memory, const std::vector<Vec3>* polished) {
  PolishedOutput out;
  // Lloyd steps left these defects as they are; more of them move them little. (man.off at 5k:
  // each of topology control's 5 rounds polished the same 15-20 defects again, 10 steps a round,
  // a third of the run; 5.9 s → 4.7 s. On the corpus the outputs are as good on average.)
  // Away from settings.around (the seeds within kAroundRings of it in this round's
  // triangulation), nothing is polished either.
  std::vector<Index> near;
  const auto settled = [&](const Triangle& t) {
    const auto is_near = [&](Index s) { return std::binary_search(near.begin(), near.end(), s); };
    return (polished && std::all_of(t.begin(), t.end(),
                                    [&](Index s) {
                                      return s < polished->size() && (*polished)[s] == seeds[s];
                                    })) ||
           (!settings.around.empty() && std::none_of(t.begin(), t.end(), is_near));
  };
  std::vector<Index> moving;
  const TrianglePieces pieces(surface, edge_length_for(surface_area(surface), seeds.size()));
  for (int round = 0;; ++round) {
    const RestrictedVoronoiDiagram rvd(surface, seeds, memory.traversal);
    MultiNerveBuilder& rdt = memory.nerve;
    rdt.for_diagram(rvd);
    CellCoverage& coverage = memory.coverage;
    coverage.for_pieces(pieces);
    std::vector<PolygonSink*> sinks{&rdt, &coverage, &memory.stop};
    if (memory.piece_shapes) {  // kept up for topology control
      memory.piece_shapes->for_diagram(rvd);
      sinks.push_back(&*memory.piece_shapes);
    }
    rvd.traverse(sinks, memory.traversal);
    out.mesh = rdt.result();
    out.vertex_seed = rdt.vertex_seed();
    // Polishing moves seeds: it looks at the triangles between seeds only, not at those of the
    // cells' far pieces (which topology control sees to).
    const TriangleMesh rdt_of_seeds = among_seeds(out.mesh, seeds.size());
    if (!settings.around.empty()) {
      near = settings.around;
      for (int ring = 0; ring < kAroundRings; ++ring) near = grown(near, rdt_of_seeds);
    }
    std::size_t defects = 0;
    const std::vector<Index> defective = defective_seeds(rdt_of_seeds, settled, defects);
    if (round == 0) out.defects = defects;
    // The defects' seeds and their neighbours move, except feature seeds: moving them along
    // their curves would undo the snapping (§4.3) that made the curves' chains of output edges.
    std::vector<Index> movable = grown(defective, rdt_of_seeds);
    std::erase_if(movable, [&](Index s) {
      return objective.kind(s) != SeedConstraints::Kind::surface || s >= settings.pinned_from;
    });
    // Done, also when the last round already moved all these seeds: Lloyd converged there to
    // a shape it cannot improve.
    // Out of time (issue 22), the output is as good as it gets.
    if (defective.empty() || round == settings.rounds || objective.interrupt().out_of_time() ||
        std::includes(moving.begin(), moving.end(), movable.begin(), movable.end()))
      return out;
    ++out.rounds;
    moving = std::move(movable);
    // One more ring of cells gives the moving cells room to shift within the patch, and one
    // more shapes the patch's cells.
    const std::vector<Index> margin = grown(moving, rdt_of_seeds);
    const Patch patch = sub_surface(surface, coverage.triangles_of(margin), objective.density(),
                                    pieces, coverage.balls_of(margin));
    const std::vector<Vec3> fixed = seeds;
    const PointTree tree(fixed);
    local_lloyd(patch.mesh, patch.density, grown(margin, rdt_of_seeds), moving, seeds, objective,
                settings.steps, tree, fixed);
  }
}

}  // namespace cvtmesh
