// The guaranteed last step of topology control (issue 18 item 1), whole: the triangles at the
// defects the rounds left go (make_manifold), and the holes that opens are closed again where
// that gives back the input's topology; a closed input's holes close anyway, each where that
// leaves a manifold (close_opened_holes). Topology control also tries it on each round's
// output, to keep the best round this step rescues.
#pragma once

#include <cstddef>

#include "cvtmesh/mesh.hpp"
#include "cvtmesh/topology.hpp"
#include "remesh/close_holes.hpp"

namespace cvtmesh {

class SurfaceProjector;

struct LastStep {
  std::size_t triangles_removed = 0;
  ClosedHoles closed;
};

// For a manifold `input` only (a non-manifold input's edges are features the output keeps): on
// another, `mesh` is left as it is. New vertices closing holes go onto `surface`.
LastStep finish_manifold(TriangleMesh& mesh, const TopologyReport& input,
                         const SurfaceProjector& surface);

}  // namespace cvtmesh
