// Well-spread random points on a surface: the initial seeds of a uniform remesh. Random seeds
// clump and leave gaps, which the first iterations of the optimization spend their time evening
// out; points a Poisson-disk distance apart start it about half way (bunny.off at 5k: after 5
// RCVT iterations from them, the energy of 10 from random seeds).
#pragma once

#include <cstdint>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// `count` points on the surface, about evenly spaced: Yuksel's sample elimination ("Sample
// Elimination for Generating Poisson Disk Sample Sets", Eurographics 2015) from a few times as
// many area-uniform random candidates. The same (mesh, count, seed) gives the same points on any
// thread count. Throws InvalidArgument if the surface has no area.
std::vector<Vec3> spread_samples(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed);

}  // namespace cvtmesh
