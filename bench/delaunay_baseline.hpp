// The baseline that benchmarks time their figures against in the same process (the paper's, §5):
// CGAL's 3D Delaunay triangulation of a point set, serial.
#pragma once

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <chrono>
#include <vector>

#include "cvtmesh/vec3.hpp"

namespace cvtmesh::bench {

// Seconds to triangulate `points` (the copy into CGAL's points not counted).
inline double delaunay_seconds(const std::vector<Vec3>& points) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_3> copy;
  copy.reserve(points.size());
  for (const Vec3& p : points) copy.emplace_back(p.x, p.y, p.z);
  const auto start = std::chrono::steady_clock::now();
  const CGAL::Delaunay_triangulation_3<Kernel> dt(copy.begin(), copy.end());
  benchmark::DoNotOptimize(dt.number_of_cells());
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace cvtmesh::bench
