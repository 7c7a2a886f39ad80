// Well-spread random points on a surface: the initial seeds of a remesh. Random seeds
// clump and leave gaps, which the first iterations of the optimization spend their time evening
// out; points a Poisson-disk distance apart start it about half way (bunny.off at 5k: after 5
// RCVT iterations from them, the energy of 10 from random seeds).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// `count` points on the surface, about evenly spaced: Yuksel's sample elimination ("Sample
// Elimination for Generating Poisson Disk Sample Sets", Eurographics 2015) from a few times as
// many area-uniform random candidates, in Morton order (spatial_order). The same (mesh, count,
// seed) gives the same points on any thread count. Throws InvalidArgument if the surface has no
// area.
std::vector<Vec3> spread_samples(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed);

// The same with a spacing that varies (a sizing field, issue 20): candidates picked on triangle t
// with probability ∝ weights[t], and kept about spacing(t, p) apart at a point p of triangle t
// (the target edge length there, > 0). `mesh` at about unit size (see size_exponent).
std::vector<Vec3> spread_samples(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed,
                                 const std::vector<double>& weights,
                                 const std::function<double(std::size_t, const Vec3&)>& spacing);

}  // namespace cvtmesh
