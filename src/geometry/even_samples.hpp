// Area-uniform points spread evenly over a triangle mesh, for means over the surface (the
// Hausdorff report's): stratified rather than independent, so that a mean over fewer points is
// as close to the integral as one over many independent points.
#pragma once

#include <cstdint>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// `count` points (none on a mesh without area). Triangle t gets its share of `count` by
// systematic allocation along the running area: floor(count · area before t / total + u) points
// up to t, one random offset u, so that every share is within one of count · area_t / total.
// Inside the triangle the points come from a Kronecker lattice of the unit square (the R2
// sequence, Roberts 2018) shifted at random and folded onto the triangle. Each point is uniform
// on the surface, so a mean over them is an unbiased estimate of the area-weighted mean; its
// variance is far lower than independent points' (the distance of a 1k-vertex remesh of bunny,
// fandisk or tripod to its input, either way, 30 seeds: the mean's relative standard deviation
// is 0.7-1.9% with 5,000 such points, 0.7-1.8% with 20,000 independent ones). A pure function
// of (mesh, count, seed): any thread count gives the same points, in triangle order.
std::vector<Vec3> even_area_samples(const TriangleMesh& mesh, std::size_t count,
                                    std::uint64_t seed);

}  // namespace cvtmesh
