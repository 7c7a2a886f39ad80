// Even spacing of the seeds along the feature curves. CCVT (paper §4.3) moves curve seeds along
// their curves by the gradient of the surface energy, which barely cares how they are spaced, and
// stray seeds that joined a curve leave links of 0.6 edge lengths next to ones of 1.1; the short
// links' triangles are the output's worst (joint.off). Lloyd on the curve itself evens them.
#pragma once

#include <vector>

#include "features/feature_seeds.hpp"

namespace cvtmesh {

// `steps` Jacobi steps of one-dimensional Lloyd along each curve, by length as `spacing`
// measures it (uniform: arc length): each curve seed moves to the middle of its 1D Voronoi cell,
// whose ends are halfway to its neighbours along the curve (the corners at an open curve's ends
// stay put). Each step keeps the seeds' order and averages each arc length with its neighbours'
// (weights 1/4, 1/2, 1/4): a diffusion, so k steps smooth the spacing over about √(k/2) seeds
// either way. A seed whose new point another seed already occupies stays where it is.
void relax_curve_seeds(std::vector<Vec3>& seeds, const SeedConstraints& c,
                       const CurveProjector& curves, const CurveSpacing& spacing, int steps);

// The constraints with every curve seed held where it is, as corner seeds are: the CCVT that
// follows relaxes the surface seeds around the evened curve seeds.
SeedConstraints curve_seeds_held(const SeedConstraints& c, const std::vector<Vec3>& seeds);

}  // namespace cvtmesh
