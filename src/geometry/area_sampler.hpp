// Area-uniform random points on a triangle mesh; sample k is a pure function of (seed, k), so
// the set of samples does not depend on how the work is split between threads.
#pragma once

#include <cstdint>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class AreaSampler {
 public:
  AreaSampler(const TriangleMesh& mesh, std::uint64_t seed);
  // Triangle t is picked with probability ∝ weights[t] (uniform inside it) instead of its area.
  AreaSampler(const TriangleMesh& mesh, std::uint64_t seed, const std::vector<double>& weights);
  struct Sample {
    Vec3 point;
    std::size_t triangle;  // the triangle it lies on
  };
  Sample sample(std::uint64_t k) const;
  Vec3 operator()(std::uint64_t k) const { return sample(k).point; }
  bool has_area() const { return !cumulative_.empty() && cumulative_.back() > 0; }

 private:
  const TriangleMesh& mesh_;
  std::uint64_t seed_;
  std::vector<double> cumulative_;  // prefix sums of triangle areas (or weights)
};

}  // namespace cvtmesh
