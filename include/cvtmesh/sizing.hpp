// Sizing of adaptive remeshing (paper §4.1): the local feature size of a surface, estimated from
// the poles of a dense sample (Amenta-Bern), and graded so that neighbouring sizes differ
// smoothly.
#pragma once

#include <cstdint>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

struct LfsSettings {
  // The sample is the mesh's vertices, which lie on the surface the mesh approximates. Area
  // samples on its flat triangles would see the polyhedron itself, whose medial axis reaches
  // every edge: sizes would fall towards 0 at each edge of a tessellated sphere. These many
  // are added nonetheless, for a mesh whose vertices are too sparse for its parts (a coarse
  // CAD model, whose edges are true features). Parts thinner than the sample's spacing are seen
  // thicker than they are.
  std::size_t samples = 0;
  std::uint64_t seed = 1;  // the sampling: same seed, same sizes
  // The sizes are made (1/gradation)-Lipschitz along the mesh's edges: the largest such
  // function under the raw estimate. Higher: smoother size changes (and smaller sizes near
  // thin parts' surroundings). 0: no grading, the raw estimate.
  double gradation = 1.5;
};

// The local feature size at each vertex of `mesh` (the distance to the medial axis, estimated as
// the distance to the nearest pole of the samples), in the mesh's units; 0 for a vertex used by
// no triangle. Throws InvalidArgument for a mesh without area or a negative gradation.
std::vector<double> local_feature_size(const TriangleMesh& mesh, const LfsSettings& settings = {});

}  // namespace cvtmesh
