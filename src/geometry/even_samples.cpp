#include "geometry/even_samples.hpp"

#include <tbb/parallel_for.h>

#include <cmath>

#include "geometry/random.hpp"

namespace cvtmesh {

namespace {

// The R2 sequence's steps: the inverse plastic number and its square.
constexpr double kStep1 = 0.7548776662466927, kStep2 = 0.5698402909980532;

}  // namespace

std::vector<Vec3> even_area_samples(const TriangleMesh& mesh, std::size_t count,
                                    std::uint64_t seed) {
  const std::size_t triangles = mesh.triangles.size();
  std::vector<double> before(triangles + 1, 0.0);  // running area
  for (std::size_t t = 0; t < triangles; ++t) {
    const auto [a, b, c] = mesh.corners(t);
    before[t + 1] = before[t] + triangle_area(a, b, c);
  }
  const double total = before[triangles];
  if (count == 0 || !(total > 0)) return {};
  // first[t]: the first point of triangle t; the last bound is `count` exactly, whatever the
  // rounding of the running sum.
  CounterRng offset_rng(seed, ~std::uint64_t{0});
  const double offset = offset_rng.uniform(), scale = static_cast<double>(count) / total;
  std::vector<std::size_t> first(triangles + 1);
  for (std::size_t t = 0; t < triangles; ++t)
    first[t] = std::min(count, static_cast<std::size_t>(std::floor(before[t] * scale + offset)));
  first[triangles] = count;
  std::vector<Vec3> points(count);
  tbb::parallel_for(std::size_t{0}, triangles, [&](std::size_t t) {
    if (first[t + 1] <= first[t]) return;
    const auto [a, b, c] = mesh.corners(t);
    CounterRng rng(seed, t);
    double u = rng.uniform(), v = rng.uniform();
    for (std::size_t k = first[t]; k < first[t + 1]; ++k) {
      u += kStep1, v += kStep2;
      u -= std::floor(u), v -= std::floor(v);
      // The square's half beyond the diagonal, turned about its centre onto the other half.
      const double s = u + v > 1 ? 1 - u : u, r = u + v > 1 ? 1 - v : v;
      points[k] = a + s * (b - a) + r * (c - a);
    }
  });
  return points;
}

}  // namespace cvtmesh
