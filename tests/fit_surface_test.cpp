// Fitting the output to the input (finish/fit_surface): chords of a curved surface move so that
// the surface lies between vertices and triangle middles, flat parts and pinned vertices stay,
// and θmin and Qmin never fall.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/topology.hpp"
#include "finish/fit_surface.hpp"
#include "geometry/surface_projector.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

std::vector<bool> all(const TriangleMesh& m) {
  return std::vector<bool>(m.vertices.size(), true);
}

// A coarse icosphere (edges about a third of the radius) against a fine one: every vertex on the
// sphere, every chord inside it, until the fit moves the vertices out.
TEST(FitSurface, HalvesTheMeanDistanceOfACoarseSphere) {
  const TriangleMesh fine = testing::icosphere(6);
  TriangleMesh coarse = testing::icosphere(2);
  const SurfaceProjector surface(fine);
  for (Vec3& v : coarse.vertices) v = surface.nearest(v).point;
  const TriangleMesh before = coarse;
  const HausdorffReport d0 = hausdorff_distance(coarse, fine);
  const QualityReport q0 = measure_quality(coarse);
  const SurfaceFit fit = fit_to_surface(coarse, surface, all(coarse), 2);
  const HausdorffReport d1 = hausdorff_distance(coarse, fine);
  const QualityReport q1 = measure_quality(coarse);
  EXPECT_EQ(fit.vertices_moved, coarse.vertices.size());
  EXPECT_LT(d1.mean, 0.5 * d0.mean);
  EXPECT_LT(d1.max, d0.max);
  EXPECT_GE(q1.angle_min_deg, q0.angle_min_deg);
  EXPECT_GE(q1.q_min, q0.q_min);
  EXPECT_EQ(coarse.triangles, before.triangles);
  // Outwards, by less than the chords' sag (a level-2 icosphere's is about 1.5% of the radius).
  for (const Vec3& v : coarse.vertices) {
    EXPECT_GT(norm(v), 1.0);
    EXPECT_LT(norm(v), 1.015);
  }
}

TEST(FitSurface, LeavesFlatPartsAndPinnedVerticesWhereTheyAre) {
  const TriangleMesh disk = testing::disk(6, 16);
  TriangleMesh copy = disk;
  const SurfaceProjector surface(disk);
  const SurfaceFit flat = fit_to_surface(copy, surface, all(copy), 2);
  EXPECT_LT(flat.offset_max, 1e-12);

  const TriangleMesh fine = testing::icosphere(5);
  TriangleMesh coarse = testing::icosphere(2);
  const SurfaceProjector sphere(fine);
  for (Vec3& v : coarse.vertices) v = sphere.nearest(v).point;
  const TriangleMesh before = coarse;
  std::vector<bool> movable = all(coarse);
  for (std::size_t v = 0; v < movable.size(); v += 3) movable[v] = false;
  fit_to_surface(coarse, sphere, movable, 2);
  for (std::size_t v = 0; v < movable.size(); ++v) {
    if (!movable[v]) {
      EXPECT_EQ(coarse.vertices[v], before.vertices[v]);
    }
  }
}

// A badly shaped triangle sets the floors: the fit may not make the mesh's worst triangle worse,
// and the result is the same on one thread as on all.
TEST(FitSurface, NeverLowersTheWorstTriangleAndDoesNotDependOnTheThreads) {
  const TriangleMesh fine = testing::torus(1, 0.4, 96, 48);
  TriangleMesh coarse = testing::torus(1, 0.4, 12, 6);
  const SurfaceProjector surface(fine);
  coarse.vertices[5] = coarse.vertices[5] + 0.6 * (coarse.vertices[6] - coarse.vertices[5]);
  for (Vec3& v : coarse.vertices) v = surface.nearest(v).point;
  const QualityReport q0 = measure_quality(coarse);
  TriangleMesh one = coarse;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    fit_to_surface(one, surface, all(one), 2);
  }
  fit_to_surface(coarse, surface, all(coarse), 2);
  EXPECT_EQ(one.vertices, coarse.vertices);
  const QualityReport q1 = measure_quality(coarse);
  EXPECT_GE(q1.angle_min_deg, q0.angle_min_deg);
  EXPECT_GE(q1.q_min, q0.q_min);
}

// A triangle at one of the input's narrow angles keeps its own shape as its floor; the others
// keep the worst of theirs: with the bad triangle's vertex said to stand at a narrow angle, the
// fit may not take the triangles away from it below where the worst of them was.
TEST(FitSurface, ATriangleAtANarrowAngleDoesNotLowerTheFloorOfTheOthers) {
  const TriangleMesh fine = testing::torus(1, 0.4, 96, 48);
  TriangleMesh coarse = testing::torus(1, 0.4, 12, 6);
  const SurfaceProjector surface(fine);
  // Uneven spacing, so that the chords sag by different amounts and the moves change shapes.
  for (std::size_t v = 0; v < coarse.vertices.size(); ++v) {
    const double k = static_cast<double>(v);
    coarse.vertices[v] += 0.04 * Vec3{std::sin(7.3 * k), std::cos(5.1 * k), std::sin(3.7 * k)};
  }
  coarse.vertices[5] = coarse.vertices[5] + 0.85 * (coarse.vertices[6] - coarse.vertices[5]);
  for (Vec3& v : coarse.vertices) v = surface.nearest(v).point;
  std::vector<double> narrow_at(coarse.vertices.size(), 0);
  narrow_at[5] = 10;
  const auto worst_away = [&](const TriangleMesh& m) {
    double worst = 180;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const Triangle& f = m.triangles[t];
      if (f[0] == 5 || f[1] == 5 || f[2] == 5) continue;
      const auto [a, b, c] = m.corners(t);
      worst = std::min(worst, triangle_shape(a, b, c).min_angle);
    }
    return worst;
  };
  const double before = worst_away(coarse);
  TriangleMesh unflagged = coarse;
  ASSERT_LT(measure_quality(coarse).angle_min_deg, before - 5);  // the bad one is far worse
  fit_to_surface(coarse, surface, all(coarse), 2, narrow_at);
  EXPECT_GE(worst_away(coarse), before);
  // Without the narrow angle, the bad triangle's floor holds for all: the same fit takes the
  // others below `before` (else this mesh would not show the difference).
  fit_to_surface(unflagged, surface, all(unflagged), 2);
  EXPECT_LT(worst_away(unflagged), before);
}

// In a remesh, last: the mean distance to a torus falls by a third or more, the worst triangle
// does not get worse, the topology stays. On a cube, whose output lies in its faces and along its
// creases, nothing moves.
TEST(FitSurface, RemeshEndsWithItAndReportsIt) {
  const TriangleMesh torus = testing::torus(1, 0.35, 120, 48);
  RemeshSettings s;
  s.vertices = 600;
  s.fit_rounds = 0;
  const RemeshResult on_surface = remesh(torus, s);
  s.fit_rounds = RemeshSettings{}.fit_rounds;
  const RemeshResult fitted = remesh(torus, s);
  EXPECT_EQ(on_surface.vertices_fitted, 0u);
  EXPECT_GT(fitted.vertices_fitted, 500u);
  EXPECT_EQ(on_surface.vertices_on_cell_normals, 0u);
  EXPECT_GT(fitted.vertices_on_cell_normals, 300u);
  EXPECT_LT(hausdorff_distance(fitted.mesh, torus).mean,
            0.67 * hausdorff_distance(on_surface.mesh, torus).mean);
  const QualityReport q0 = measure_quality(on_surface.mesh), q1 = measure_quality(fitted.mesh);
  EXPECT_GE(q1.angle_min_deg, q0.angle_min_deg);
  EXPECT_GE(q1.q_min, q0.q_min);
  EXPECT_TRUE(same_topology(analyze_topology(fitted.mesh), analyze_topology(torus)));

  EXPECT_EQ(fitted.vertices_snapped, 0u);  // no crease: nothing to snap to

  const TriangleMesh cube = testing::cube(4);
  const RemeshResult box = remesh(cube, s);
  EXPECT_EQ(box.vertices_fitted, 0u);
  EXPECT_EQ(box.vertices_snapped, 0u);  // its creases are traced
}

// A low-poly surface remeshed finer without its features: the vertices beside its edges move onto
// them (finish/snap_to_creases), and the output's distance to it falls further than the fit
// alone takes it, θmin and Qmin kept.
TEST(FitSurface, VerticesBesideTheEdgesOfALowPolySurfaceMoveOntoThem) {
  const TriangleMesh icosahedron = testing::icosphere(0);
  RemeshSettings s;
  s.vertices = 1500;
  s.features.sharp_edges = false;
  s.fit_rounds = 0;
  const RemeshResult on_surface = remesh(icosahedron, s);
  s.fit_rounds = RemeshSettings{}.fit_rounds;
  const RemeshResult fitted = remesh(icosahedron, s);
  EXPECT_GT(fitted.vertices_snapped, 30u);
  // The fit alone: a vertex beside an edge has triangles leaning off both faces, which moves along
  // the normal cannot put back (measured at 1,500 vertices: the mean 2% lower; snapped, 35%).
  EXPECT_LT(hausdorff_distance(fitted.mesh, icosahedron).mean,
            0.75 * hausdorff_distance(on_surface.mesh, icosahedron).mean);
  const QualityReport q0 = measure_quality(on_surface.mesh), q1 = measure_quality(fitted.mesh);
  EXPECT_GE(q1.angle_min_deg, std::min(q0.angle_min_deg, 40.0));
  EXPECT_GE(q1.q_min, std::min(q0.q_min, 0.7));
  EXPECT_TRUE(same_topology(analyze_topology(fitted.mesh), analyze_topology(icosahedron)));
}

}  // namespace
}  // namespace cvtmesh
