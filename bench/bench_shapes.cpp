// The output's last step (finish/improve_shapes: flips, moves, balancing flips and short-edge
// collapses around badly shaped triangles), against projecting every vertex onto the surface
// once, measured in the same process so the ratio survives a noisy machine: the step's main cost
// is its projections.
//   BM_ImproveShapes/J: an icosphere of level 4 (2,562 vertices) with each vertex moved at random
//     by up to J% of the unit sphere's radius along it (edges are about 8% long), improved on an
//     icosphere of level 6; counters shapes_s, projections_s (every vertex once),
//     shapes_over_projections, flips, moves, collapses (J = 3 has some), and Qmin and θmin before
//     and after.
//   BM_ImproveShapesGuarded/J: the same with every vertex guarded (VertexSupport::guarded, as
//     finish/crossing_guard guards those near crossings the finishing steps made): each flip, move
//     and collapse checked for triangles passing through others (finish/near_triangles finds the
//     triangles to check); counters guarded_s, unguarded_s (BM_ImproveShapes's run),
//     guarded_over_unguarded, and the flips, moves and collapses of both.
//   BM_FitSurface/R: the same level-4 icosphere, its vertices on the level-6 one, fitted to it in R
//     rounds (finish/fit_surface); counters fit_s, projections_s, fit_over_projections, and the
//     Hausdorff mean before and after (% of the radius).
//   BM_CellNormalPoints: the same level-4 icosphere, jittered along the sphere by up to 2% of the
//     radius, its vertices the seeds on the level-6 one: their cells' centroids and normals
//     (voronoi/cell_normals) replayed from the memory of a traversal of the same seeds, as the
//     remesher does after its extraction, against the same without a memory, then the vertices
//     moved onto their cells' normal lines (finish/cell_normal_points); counters cells_s, fresh_s,
//     cells_over_fresh, move_s, step_s (both), projections_s, step_over_projections, moved, and
//     the Hausdorff mean before and after (% of the radius).
//   BM_SnapToCreases/T: an icosphere of level 5 (10,242 vertices) projected onto an icosahedron,
//     its vertices beside the icosahedron's edges moved onto them (finish/snap_to_creases) on T
//     threads; counters snap_s, projections_s (every vertex once, one thread),
//     snap_over_projections and moved (the same for any T).
//   BM_ProjectMoved/M/C: 20k points on a torus of 40k triangles (C = 0) or 384 (C = 1, each
//     triangle some 50 points wide), each moved at random by up to M% of the points' spacing,
//     projected again from their feet before (as CCVT projects its seeds every evaluation,
//     cvt/cvt_objective) against without a hint, and against CGAL's own search from the same
//     hint; counters hinted_s, fresh_s, cgal_s, hinted_over_fresh, hinted_over_cgal, differing
//     (feet the hinted and fresh searches find at different distances: must be 0) and off_cgal
//     (distances more than 1e-12 spacings from CGAL's: must be 0).
#include <benchmark/benchmark.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <random>
#include <string>

#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/sampling.hpp"
#include "finish/cell_normal_points.hpp"
#include "finish/fit_surface.hpp"
#include "finish/improve_shapes.hpp"
#include "finish/snap_to_creases.hpp"
#include "geometry/surface_projector.hpp"
#include "support/shapes.hpp"
#include "voronoi/cell_normals.hpp"

namespace {

using namespace cvtmesh;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The baseline: each of `points` projected onto `surface` once.
double seconds_to_project(const SurfaceProjector& surface, const std::vector<Vec3>& points) {
  const auto start = std::chrono::steady_clock::now();
  double sum = 0;
  for (const Vec3& v : points) sum += surface.nearest(v).point.x;
  benchmark::DoNotOptimize(sum);
  return seconds_since(start);
}

// Sets the iteration's time to a step's `seconds`, with counters NAME_s, projections_s (each of
// `points` projected onto `surface` once) and NAME_over_projections.
void time_against_projections(benchmark::State& state, const std::string& name, double seconds,
                              const SurfaceProjector& surface, const std::vector<Vec3>& points) {
  const double projections_s = seconds_to_project(surface, points);
  state.SetIterationTime(seconds);
  state.counters[name + "_s"] = seconds;
  state.counters["projections_s"] = projections_s;
  state.counters[name + "_over_projections"] = seconds / projections_s;
}

// `mesh` with each vertex moved to its nearest point of `surface`.
TriangleMesh on_surface(TriangleMesh mesh, const SurfaceProjector& surface) {
  for (Vec3& v : mesh.vertices) v = surface.nearest(v).point;
  return mesh;
}

void BM_ImproveShapes(benchmark::State& state) {
  const TriangleMesh fine = testing::icosphere(6);
  const SurfaceProjector surface(fine);
  const TriangleMesh start = testing::jittered_on_sphere(
      testing::icosphere(4), 0.01 * static_cast<double>(state.range(0)), 1);
  const QualityReport before = measure_quality(start);
  for (auto _ : state) {
    TriangleMesh mesh = start;
    std::vector<Edge> no_features;
    const auto shapes_start = std::chrono::steady_clock::now();
    const ShapeImprovement done = improve_shapes(mesh, surface, nullptr, {}, no_features, 5);
    time_against_projections(state, "shapes", seconds_since(shapes_start), surface, start.vertices);
    const QualityReport after = measure_quality(mesh);
    state.counters["flips"] = static_cast<double>(done.flips);
    state.counters["moves"] = static_cast<double>(done.moves);
    state.counters["collapses"] = static_cast<double>(done.collapses);
    state.counters["q_min_before"] = before.q_min;
    state.counters["q_min_after"] = after.q_min;
    state.counters["theta_min_before"] = before.angle_min_deg;
    state.counters["theta_min_after"] = after.angle_min_deg;
  }
}
BENCHMARK(BM_ImproveShapes)->Arg(1)->Arg(2)->Arg(3)->UseManualTime()->Unit(benchmark::kMillisecond);

void BM_ImproveShapesGuarded(benchmark::State& state) {
  const TriangleMesh fine = testing::icosphere(6);
  const SurfaceProjector surface(fine);
  const TriangleMesh start = testing::jittered_on_sphere(
      testing::icosphere(4), 0.01 * static_cast<double>(state.range(0)), 1);
  std::vector<VertexSupport> guarded(start.vertices.size());
  for (VertexSupport& s : guarded) s.guarded = true;
  for (auto _ : state) {
    std::vector<Edge> no_features;
    TriangleMesh plain = start;
    auto t0 = std::chrono::steady_clock::now();
    const ShapeImprovement a = improve_shapes(plain, surface, nullptr, {}, no_features, 5);
    const double unguarded_s = seconds_since(t0);
    TriangleMesh checked = start;
    t0 = std::chrono::steady_clock::now();
    const ShapeImprovement b = improve_shapes(checked, surface, nullptr, guarded, no_features, 5);
    const double guarded_s = seconds_since(t0);
    state.SetIterationTime(guarded_s);
    state.counters["guarded_s"] = guarded_s;
    state.counters["unguarded_s"] = unguarded_s;
    state.counters["guarded_over_unguarded"] = guarded_s / unguarded_s;
    state.counters["flips"] = static_cast<double>(a.flips);
    state.counters["moves"] = static_cast<double>(a.moves);
    state.counters["collapses"] = static_cast<double>(a.collapses);
    state.counters["guarded_flips"] = static_cast<double>(b.flips);
    state.counters["guarded_moves"] = static_cast<double>(b.moves);
    state.counters["guarded_collapses"] = static_cast<double>(b.collapses);
  }
}
BENCHMARK(BM_ImproveShapesGuarded)->Arg(1)->Arg(3)->UseManualTime()->Unit(benchmark::kMillisecond);

void BM_FitSurface(benchmark::State& state) {
  const TriangleMesh fine = testing::icosphere(6);
  const SurfaceProjector surface(fine);
  const TriangleMesh start = on_surface(testing::icosphere(4), surface);
  const std::vector<bool> movable(start.vertices.size(), true);
  const double mean_before = hausdorff_distance(start, fine).mean;
  for (auto _ : state) {
    TriangleMesh mesh = start;
    const auto fit_start = std::chrono::steady_clock::now();
    fit_to_surface(mesh, surface, movable, static_cast<int>(state.range(0)));
    time_against_projections(state, "fit", seconds_since(fit_start), surface, start.vertices);
    state.counters["hd_mean_before_pct"] = 100 * mean_before;
    state.counters["hd_mean_after_pct"] = 100 * hausdorff_distance(mesh, fine).mean;
  }
}
BENCHMARK(BM_FitSurface)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMillisecond);

void BM_CellNormalPoints(benchmark::State& state) {
  const TriangleMesh fine = testing::icosphere(6);
  const SurfaceProjector surface(fine);
  const TriangleMesh start =
      on_surface(testing::jittered_on_sphere(testing::icosphere(4), 0.02, 1), surface);
  const std::vector<bool> movable(start.vertices.size(), true);
  const double mean_before = hausdorff_distance(start, fine).mean;
  for (auto _ : state) {
    TriangleMesh mesh = start;
    TraversalMemory fresh, replayed;
    cell_normals(fine, start.vertices, replayed);  // the extraction's traversal
    const auto fresh_start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(cell_normals(fine, start.vertices, fresh));
    const double fresh_s = seconds_since(fresh_start);
    const auto cells_start = std::chrono::steady_clock::now();
    const std::vector<CellNormal> cells = cell_normals(fine, start.vertices, replayed);
    const double cells_s = seconds_since(cells_start);
    const auto move_start = std::chrono::steady_clock::now();
    const std::size_t moved = move_onto_cell_normals(mesh, start.vertices, cells, surface, movable);
    const double move_s = seconds_since(move_start);
    time_against_projections(state, "step", cells_s + move_s, surface, start.vertices);
    state.counters["move_s"] = move_s;
    state.counters["cells_s"] = cells_s;
    state.counters["fresh_s"] = fresh_s;
    state.counters["cells_over_fresh"] = cells_s / fresh_s;
    state.counters["moved"] = static_cast<double>(moved);
    state.counters["hd_mean_before_pct"] = 100 * mean_before;
    state.counters["hd_mean_after_pct"] = 100 * hausdorff_distance(mesh, fine).mean;
  }
}
BENCHMARK(BM_CellNormalPoints)->UseManualTime()->Unit(benchmark::kMillisecond);

void BM_SnapToCreases(benchmark::State& state) {
  const TriangleMesh icosahedron = testing::icosphere(0);
  const SurfaceProjector surface(icosahedron);
  const TriangleMesh start = on_surface(testing::icosphere(5), surface);
  const std::vector<bool> movable(start.vertices.size(), true);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    TriangleMesh mesh = start;
    const auto snap_start = std::chrono::steady_clock::now();
    const std::size_t moved = snap_to_creases(mesh, icosahedron, {}, surface, movable);
    time_against_projections(state, "snap", seconds_since(snap_start), surface, start.vertices);
    state.counters["moved"] = static_cast<double>(moved);
  }
}
BENCHMARK(BM_SnapToCreases)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMillisecond);

// CGAL's own search for the nearest point, with the same hint: the baseline of BM_ProjectMoved.
class CgalNearest {
 public:
  explicit CgalNearest(const TriangleMesh& mesh) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto [a, b, c] = mesh.corners(t);
      triangles_.emplace_back(point(a), point(b), point(c));
    }
    tree_.insert(triangles_.begin(), triangles_.end());
    tree_.build();
    tree_.do_not_accelerate_distance_queries();
  }
  // `hint` on triangle `t` of the mesh.
  double distance(const Vec3& p, const Vec3& hint, std::size_t t) const {
    const auto found = tree_.closest_point_and_primitive(
        point(p), {point(hint), triangles_.begin() + static_cast<std::ptrdiff_t>(t)});
    return std::sqrt(CGAL::squared_distance(point(p), found.first));
  }

 private:
  using Kernel = CGAL::Simple_cartesian<double>;
  using Triangles = std::vector<Kernel::Triangle_3>;
  using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
  static Kernel::Point_3 point(const Vec3& v) { return {v.x, v.y, v.z}; }
  Triangles triangles_;
  CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>> tree_;
};

void BM_ProjectMoved(benchmark::State& state) {
  const bool coarse = state.range(1) != 0;
  const TriangleMesh torus = coarse ? testing::torus(1.0, 0.3, 24, 8)  // 384 triangles
                                    : testing::torus(1.0, 0.3, 200, 100);
  const SurfaceProjector surface(torus);
  const CgalNearest cgal(torus);
  const std::size_t n = 20'000;
  const std::vector<Vec3> points = sample_surface(torus, n, 1);
  std::vector<SurfaceProjector::Foot> feet;
  for (const Vec3& p : points) feet.push_back(surface.nearest(p));
  const double spacing = std::sqrt(surface_area(torus) / static_cast<double>(n));
  std::mt19937_64 random(2);
  std::uniform_real_distribution<double> u(-1, 1);
  const double step = 0.01 * static_cast<double>(state.range(0)) * spacing;
  std::vector<Vec3> moved = points;
  for (Vec3& p : moved) p = p + step * Vec3{u(random), u(random), u(random)};
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    std::vector<SurfaceProjector::Foot> hinted(n), fresh(n);
    for (std::size_t k = 0; k < n; ++k) hinted[k] = surface.nearest(moved[k], feet[k]);
    const double hinted_s = seconds_since(start);
    start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < n; ++k) fresh[k] = surface.nearest(moved[k]);
    const double fresh_s = seconds_since(start);
    start = std::chrono::steady_clock::now();
    std::vector<double> by_cgal(n);
    for (std::size_t k = 0; k < n; ++k)
      by_cgal[k] =
          cgal.distance(moved[k], feet[k].point, surface.surface_triangle(feet[k].triangle));
    const double cgal_s = seconds_since(start);
    state.SetIterationTime(hinted_s);
    std::size_t differing = 0, off_cgal = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double d = distance(moved[k], hinted[k].point);
      differing += d != distance(moved[k], fresh[k].point);
      off_cgal += std::abs(d - by_cgal[k]) > 1e-12 * spacing;
    }
    state.counters["hinted_s"] = hinted_s;
    state.counters["fresh_s"] = fresh_s;
    state.counters["cgal_s"] = cgal_s;
    state.counters["hinted_over_fresh"] = hinted_s / fresh_s;
    state.counters["hinted_over_cgal"] = hinted_s / cgal_s;
    state.counters["differing"] = static_cast<double>(differing);
    state.counters["off_cgal"] = static_cast<double>(off_cgal);
  }
}
BENCHMARK(BM_ProjectMoved)
    ->ArgsProduct({{10, 50}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
