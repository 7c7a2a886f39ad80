// The initial seeds of a uniform remesh: as many as asked, on the surface, evenly spread (no two
// close, a lower CVT energy than random points), the same on any thread count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/rvd.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "cvtmesh/sampling.hpp"
#include "geometry/area_sampler.hpp"
#include "geometry/spatial_order.hpp"
#include "geometry/spread_samples.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// The smallest distance between two of the points.
double closest_pair(const std::vector<Vec3>& points) {
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < points.size(); ++a)
    for (std::size_t b = a + 1; b < points.size(); ++b)
      closest = std::min(closest, distance(points[a], points[b]));
  return closest;
}

double cvt_energy(const TriangleMesh& surface, const std::vector<Vec3>& seeds) {
  const RestrictedVoronoiDiagram rvd(surface, seeds);
  CellIntegrator integrator(rvd);
  rvd.traverse(integrator);
  return integrator.result().total_energy;
}

// The distance from p to the nearest of the mesh's triangles' planes it projects into; for the
// test's convex meshes, the distance to the surface.
double off_surface(const TriangleMesh& mesh, const Vec3& p) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const Vec3 n = cross(b - a, c - a);
    nearest = std::min(nearest, std::abs(dot(p - a, n)) / norm(n));
  }
  return nearest;
}

TEST(SpreadSamples, AsManyAsAskedOnTheSurfaceAndNoTwoClose) {
  const TriangleMesh sphere = icosphere(3);
  const std::size_t n = 1000;
  const std::vector<Vec3> spread = spread_samples(sphere, n, 1);
  ASSERT_EQ(spread.size(), n);
  for (const Vec3& p : spread) {
    EXPECT_LT(off_surface(sphere, p), 1e-12);
    EXPECT_LE(norm(p), 1 + 1e-12);
  }
  // Discs of radius r packed as densely as discs can be cover 2√3 r² each: r_max is the largest
  // radius n of them can have on the area. Sample elimination keeps points about 0.7 r_max
  // apart or more; random points come far closer.
  const double r_max = std::sqrt(surface_area(sphere) / (2 * std::sqrt(3.0) * n));
  EXPECT_GT(closest_pair(spread), 0.5 * r_max);
  EXPECT_LT(closest_pair(sample_surface(sphere, n, 1)), 0.1 * r_max);
  // Nearer to centroidal: the optimization starts further along.
  EXPECT_LT(cvt_energy(sphere, spread), 0.75 * cvt_energy(sphere, sample_surface(sphere, n, 1)));
}

TEST(SpreadSamples, TheSameOnAnyThreadCountAndForTheSameSeedOnly) {
  const TriangleMesh torus_mesh = torus(1.0, 0.3, 64, 24);
  std::vector<Vec3> one, two;
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
    one = spread_samples(torus_mesh, 20'000, 7);
  }
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
    two = spread_samples(torus_mesh, 20'000, 7);
  }
  EXPECT_TRUE(one == two);
  EXPECT_FALSE(one == spread_samples(torus_mesh, 20'000, 8));
}

// Issue 20: the seeds of a sizing field are spread about its target length apart, as many where
// it asks for many, and as uniform ones no two close.
TEST(SpreadSamples, FollowATargetLengthThatVaries) {
  const TriangleMesh square = mapped_grid(40, 40, [](double u, double v) { return Vec3{u, v, 0}; });
  // Three times as long at x = 1 as at x = 0.
  const auto length = [](const Vec3& p) { return 0.02 * (1 + 2 * p.x); };
  std::vector<double> weights(square.triangles.size());
  double count = 0;
  for (std::size_t t = 0; t < weights.size(); ++t) {
    const auto [a, b, c] = square.corners(t);
    double per_area = 0;  // points per area: one per √3/2 h²
    for (const Vec3& p : {a, b, c})
      per_area += 1 / (std::sqrt(3.0) / 2 * length(p) * length(p)) / 3;
    weights[t] = triangle_area(a, b, c) * per_area;
    count += weights[t];
  }
  const auto n = static_cast<std::size_t>(count);
  const auto spacing = [&](std::size_t, const Vec3& p) { return length(p); };
  const std::vector<Vec3> spread = spread_samples(square, n, 1, weights, spacing);
  ASSERT_EQ(spread.size(), n);
  // As many in the finest third as the lengths ask for: ∫ 1 / (√3/2 h²) over x in [0, 1/3].
  const double h0 = 0.02,
               in_first_third = (1 - 1 / (1 + 2.0 / 3)) / (2 * std::sqrt(3.0) / 2 * h0 * h0);
  const auto first_third =
      std::count_if(spread.begin(), spread.end(), [](const Vec3& p) { return p.x < 1.0 / 3; });
  EXPECT_NEAR(static_cast<double>(first_third), in_first_third, 0.1 * in_first_third);
  // No two closer than a quarter of the smaller of their lengths (half of r_max, as for uniform
  // points); points drawn at random with the same density come far closer.
  const auto closest_relative = [&](const std::vector<Vec3>& points) {
    double closest = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < points.size(); ++a)
      for (std::size_t b = a + 1; b < points.size(); ++b)
        closest = std::min(closest, distance(points[a], points[b]) /
                                        std::min(length(points[a]), length(points[b])));
    return closest;
  };
  EXPECT_GT(closest_relative(spread), 0.25);
  const AreaSampler random(square, 1, weights);
  std::vector<Vec3> drawn(n);
  for (std::size_t k = 0; k < n; ++k) drawn[k] = random(k);
  EXPECT_LT(closest_relative(drawn), 0.05);
}

// In Morton order, as the remesher's input triangles are, so that the RVD reads the arrays
// indexed by seed in runs (issue 19 item 1); with a varying length too.
TEST(SpreadSamples, ComeInSpatialOrder) {
  const auto in_order = [](const std::vector<Vec3>& points) {
    const std::vector<Index> order = spatial_order(points);
    for (Index k = 0; k < order.size(); ++k)
      if (order[k] != k) return false;
    return true;
  };
  const TriangleMesh torus_mesh = torus(1.0, 0.3, 64, 24);
  EXPECT_TRUE(in_order(spread_samples(torus_mesh, 3'000, 5)));
  const std::vector<double> weights(torus_mesh.triangles.size(), 1.0);
  EXPECT_TRUE(in_order(spread_samples(
      torus_mesh, 3'000, 5, weights, [](std::size_t, const Vec3& p) { return 0.02 * (2 + p.x); })));
  // Which the candidates' random order is not.
  EXPECT_FALSE(in_order(sample_surface(torus_mesh, 3'000, 5)));
}

TEST(SpreadSamples, TinyAndHugeSurfacesAreSpreadAlike) {
  const TriangleMesh sphere = icosphere(2);
  const std::vector<Vec3> unit = spread_samples(sphere, 200, 1);
  for (const int exponent : {-600, 600}) {
    const std::vector<Vec3> scaled =
        spread_samples(scaled_by_power_of_two(sphere, exponent), 200, 1);
    ASSERT_EQ(scaled.size(), unit.size());
    for (std::size_t k = 0; k < unit.size(); ++k)
      EXPECT_EQ(scaled[k], scaled_by_power_of_two(unit[k], exponent));
  }
}

TEST(SpreadSamples, ASurfaceWithoutAreaIsRefused) {
  TriangleMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.triangles = {{0, 1, 2}};
  EXPECT_THROW(spread_samples(flat, 10, 1), InvalidArgument);
}

}  // namespace
}  // namespace cvtmesh
