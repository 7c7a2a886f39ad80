#include "remesh/last_step.hpp"

#include "geometry/surface_projector.hpp"
#include "remesh/make_manifold.hpp"

namespace cvtmesh {

LastStep finish_manifold(TriangleMesh& mesh, const TopologyReport& input,
                         const SurfaceProjector& surface) {
  LastStep step;
  if (!input.is_manifold()) return step;
  const std::vector<Triangle> removed = make_manifold(mesh, input.orientable);
  step.triangles_removed = removed.size();
  // A closed input's output may have holes with nothing removed (a Voronoi edge that missed
  // the surface where it should cross it): they close too (close_opened_holes finds none fast).
  if (!removed.empty() || input.is_closed())
    step.closed = close_opened_holes(mesh, removed, input, input.orientable,
                                     [&](const Vec3& p) { return surface.nearest(p).point; });
  step.triangles_removed += step.closed.lone_triangles;
  return step;
}

}  // namespace cvtmesh
