// Output vertices onto their cells' normal lines (finish/cell_normal_points, voronoi/cell_normals):
// a vertex on the flank of a tip narrower than an edge moves onto the tip, no triangle gets worse
// than it was (or than the aim), and nothing depends on the thread count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

#include "cvtmesh/quality.hpp"
#include "finish/cell_normal_points.hpp"
#include "geometry/surface_projector.hpp"
#include "quality/min_shape.hpp"
#include "support/shapes.hpp"
#include "voronoi/cell_normals.hpp"

namespace cvtmesh {
namespace {

// A unit square with a cone spike at its centre, `r` wide at its foot and `h` high.
Vec3 spike(double u, double v, double r, double h) {
  const double d = std::hypot(u - 0.5, v - 0.5);
  return {u, v, h * std::max(0.0, 1 - d / r)};
}

// The apex's distance to the mesh.
double apex_gap(const TriangleMesh& m, const Vec3& apex) {
  return SurfaceProjector(m).distance_to(apex);
}

std::vector<CellNormal> cells_of(const TriangleMesh& surface, const std::vector<Vec3>& seeds) {
  TraversalMemory memory;
  return cell_normals(surface, seeds, memory);
}

// A 6 × 6 grid over the spiked square (edges 1/6, the spike 0.24 wide), its middle vertex moved
// from the apex down the spike's flank: its cell holds the tip, whose normal line through the
// cell's centroid meets the spike higher up. The vertex moves there, the output cuts less of the
// tip off, and the triangles stay as well shaped as they were, or as the aim.
TEST(CellNormalPoints, AVertexOnTheFlankOfATipNarrowerThanAnEdgeMovesOntoTheTip) {
  constexpr double r = 0.12, h = 0.2;
  const TriangleMesh surface =
      testing::mapped_grid(120, 120, [](double u, double v) { return spike(u, v, r, h); });
  TriangleMesh coarse =
      testing::mapped_grid(6, 6, [](double u, double v) { return spike(u, v, r, h); });
  const Vec3 apex{0.5, 0.5, h};
  const auto middle = static_cast<std::size_t>(
      std::find(coarse.vertices.begin(), coarse.vertices.end(), apex) - coarse.vertices.begin());
  ASSERT_LT(middle, coarse.vertices.size());
  coarse.vertices[middle] = spike(0.5 + 0.6 * r, 0.5, r, h);  // on the flank
  const std::vector<Vec3> seeds = coarse.vertices;
  const double before = apex_gap(coarse, apex);
  const TriangleMesh start = coarse;
  const SurfaceProjector projector(surface);
  const std::size_t moved =
      move_onto_cell_normals(coarse, seeds, cells_of(surface, seeds), projector,
                             std::vector<bool>(coarse.vertices.size(), true));
  EXPECT_GE(moved, 1u);
  EXPECT_LT(apex_gap(coarse, apex), 0.7 * before);                  // measured: 0.137 -> 0.078
  EXPECT_LT(projector.distance_to(coarse.vertices[middle]), 1e-9);  // on the surface
  for (std::size_t t = 0; t < coarse.triangles.size(); ++t) {
    const auto [a0, b0, c0] = start.corners(t);
    const auto [a1, b1, c1] = coarse.corners(t);
    const MinShape was = min_shape(a0, b0, c0), now = min_shape(a1, b1, c1);
    EXPECT_GE(now.min_angle, std::min(was.min_angle, 40.0) - 1e-9) << t;
    EXPECT_GE(now.quality, std::min(was.quality, 0.7) - 1e-12) << t;
  }
  // The grid's rim (edges of one triangle) stays.
  for (std::size_t v = 0; v < coarse.vertices.size(); ++v) {
    const Vec3& x = start.vertices[v];
    if (x.x == 0 || x.y == 0 || x.x == 1 || x.y == 1) {
      EXPECT_EQ(coarse.vertices[v], x);
    }
  }
}

// A vertex that stands at no seed, or is not movable, stays; an empty cell list moves nothing.
TEST(CellNormalPoints, OnlyMovableVerticesAtSeedsMove) {
  const TriangleMesh surface = testing::icosphere(5);
  TriangleMesh coarse = testing::jittered_on_sphere(testing::icosphere(2), 0.05, 3);
  const SurfaceProjector projector(surface);
  for (Vec3& x : coarse.vertices) x = projector.nearest(x).point;
  const std::vector<Vec3> seeds = coarse.vertices;
  const std::vector<CellNormal> cells = cells_of(surface, seeds);
  TriangleMesh pinned = coarse;
  EXPECT_EQ(move_onto_cell_normals(pinned, seeds, cells, projector,
                                   std::vector<bool>(pinned.vertices.size(), false)),
            0u);
  EXPECT_EQ(pinned.vertices, coarse.vertices);
  TriangleMesh elsewhere = coarse;
  const std::vector<Vec3> other(seeds.size(), Vec3{9, 9, 9});
  EXPECT_EQ(move_onto_cell_normals(elsewhere, other, cells, projector,
                                   std::vector<bool>(elsewhere.vertices.size(), true)),
            0u);
  TriangleMesh free = coarse;
  EXPECT_GT(move_onto_cell_normals(free, seeds, cells, projector,
                                   std::vector<bool>(free.vertices.size(), true)),
            coarse.vertices.size() / 2);
  for (const Vec3& x : free.vertices) EXPECT_LT(projector.distance_to(x), 1e-9);
}

// The cells' centroids and normals, and the moves, are the same on one thread and on two.
TEST(CellNormalPoints, DoNotDependOnTheThreadCount) {
  const TriangleMesh surface = testing::torus(1, 0.35, 160, 64);
  TriangleMesh coarse = testing::torus(1, 0.35, 40, 16);
  const SurfaceProjector projector(surface);
  for (Vec3& x : coarse.vertices) x = projector.nearest(x + Vec3{0.013, -0.007, 0.004}).point;
  const std::vector<Vec3> seeds = coarse.vertices;
  const auto run = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                    static_cast<std::size_t>(threads));
    const std::vector<CellNormal> cells = cells_of(surface, seeds);
    TriangleMesh m = coarse;
    move_onto_cell_normals(m, seeds, cells, projector, std::vector<bool>(m.vertices.size(), true));
    return std::pair{cells, m.vertices};
  };
  const auto [cells1, moved1] = run(1);
  const auto [cells2, moved2] = run(2);
  ASSERT_EQ(cells1.size(), cells2.size());
  for (std::size_t s = 0; s < cells1.size(); ++s) {
    EXPECT_EQ(cells1[s].centroid, cells2[s].centroid);
    EXPECT_EQ(cells1[s].normal, cells2[s].normal);
  }
  EXPECT_EQ(moved1, moved2);
}

}  // namespace
}  // namespace cvtmesh
