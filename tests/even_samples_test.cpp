// Evenly spread area samples (geometry/even_samples), the Hausdorff report's: each triangle's
// share of the count within one, every point on its triangle, the same points on any thread
// count, and a mean over them far closer to the integral than independent samples give.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "geometry/area_sampler.hpp"
#include "geometry/even_samples.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// Triangles far apart, of areas 1, 2, ..., n (legs 1 and 2k, in the plane z = 10k): each point
// tells its triangle by its height.
TriangleMesh separate_triangles(int n) {
  TriangleMesh mesh;
  for (int k = 0; k < n; ++k) {
    const double z = 10.0 * k;
    const auto first = static_cast<Index>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), {{0, 0, z}, {1, 0, z}, {0, 2.0 * (k + 1), z}});
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

TEST(EvenAreaSamples, EachTriangleGetsItsShareWithinOneAndPointsLieOnIt) {
  const int n = 12;
  const TriangleMesh mesh = separate_triangles(n);
  const double total = n * (n + 1) / 2.0;
  for (const std::size_t count : {7u, 100u, 1001u}) {
    const std::vector<Vec3> points = even_area_samples(mesh, count, 5);
    ASSERT_EQ(points.size(), count);
    std::vector<std::size_t> got(n, 0);
    int previous = 0;
    for (const Vec3& p : points) {
      const int k = static_cast<int>(std::lround(p.z / 10));
      ASSERT_GE(k, previous) << "points come in triangle order";
      previous = k;
      ++got[k];
      // Inside the triangle x/1 + y/(2(k+1)) <= 1, x, y >= 0.
      EXPECT_GE(p.x, 0);
      EXPECT_GE(p.y, 0);
      EXPECT_LE(p.x + p.y / (2.0 * (k + 1)), 1 + 1e-12);
    }
    for (int k = 0; k < n; ++k)
      EXPECT_LT(std::abs(static_cast<double>(got[k]) - count * (k + 1) / total), 1.0)
          << "triangle " << k << " of " << count;
  }
}

TEST(EvenAreaSamples, NoAreaGivesNoPoints) {
  TriangleMesh flat = separate_triangles(3);
  for (Vec3& v : flat.vertices) v.y = 0;  // every triangle a segment
  EXPECT_TRUE(even_area_samples(flat, 100, 1).empty());
  EXPECT_TRUE(even_area_samples(separate_triangles(3), 0, 1).empty());
  // A triangle without area among others gets none.
  TriangleMesh mixed = separate_triangles(3);
  mixed.vertices[5].y = 0;  // the second triangle's apex (z = 10)
  const std::vector<Vec3> points = even_area_samples(mixed, 500, 1);
  EXPECT_EQ(points.size(), 500u);
  for (const Vec3& p : points) EXPECT_NE(std::lround(p.z / 10), 1);
}

TEST(EvenAreaSamples, SameSeedSamePointsOnAnyThreadCount) {
  const TriangleMesh mesh = torus(1, 0.4, 40, 16);
  std::vector<Vec3> one;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = even_area_samples(mesh, 20'000, 3);
  }
  EXPECT_EQ(even_area_samples(mesh, 20'000, 3), one);
  EXPECT_NE(even_area_samples(mesh, 20'000, 4), one);
}

// The mean of x² over the unit square (two triangles) is 1/3. Over 30 seeds, the mean of 2,000
// even points strays at most a fifth as far as that of 2,000 independent points (whose standard
// deviation is sqrt((1/5 - 1/9) / 2000) = 0.0067): the reason the report can sample fewer.
TEST(EvenAreaSamples, MeanIsFarCloserThanIndependentSamples) {
  TriangleMesh square;
  square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const std::size_t count = 2000;
  double even_error = 0, independent_error = 0;
  const int seeds = 30;
  for (int seed = 1; seed <= seeds; ++seed) {
    double even = 0, independent = 0;
    for (const Vec3& p : even_area_samples(square, count, seed)) even += p.x * p.x;
    const AreaSampler sampler(square, seed);
    for (std::size_t k = 0; k < count; ++k) independent += std::pow(sampler(k).x, 2);
    even_error += std::pow(even / count - 1.0 / 3, 2);
    independent_error += std::pow(independent / count - 1.0 / 3, 2);
  }
  even_error = std::sqrt(even_error / seeds);
  independent_error = std::sqrt(independent_error / seeds);
  EXPECT_GT(independent_error, 0.003);  // the independent points behave as the theory says
  EXPECT_LT(even_error, 0.2 * independent_error) << even_error << " vs " << independent_error;
}

}  // namespace
}  // namespace cvtmesh
