// The output's finishing steps, after topology control and its last step (paper §4.4;
// remesh/mend_topology, remesh/last_step), in this order: flat ears at the boundary, the output
// vertices that topology control added and the feature links traced (matched to the seeds by
// position, so before anything moves them), the last flips, moves and collapses around badly
// shaped triangles (improve_shapes; obtuse boundary corners split first where that ends better),
// vertices of three triangles, the vertices beside untraced input creases moved onto them
// (snap_to_creases), and the fit to the input.
#pragma once

#include <set>
#include <vector>

#include "cvtmesh/remesh.hpp"
#include "features/feature_seeds.hpp"
#include "voronoi/cell_normals.hpp"

namespace cvtmesh {

class SurfaceProjector;

// `result.mesh`: the extraction topology control returned, after its last step (its first
// vertices the seeds, by id); `seeds`: all the seeds, those topology control added from
// `optimized_seeds` on; `cells`: per seed, its restricted cell's centroid and normal (empty: the
// vertices stay at the seeds, as with no fit). Fills `result`'s counts of what each step did, its
// feature edges, and the vertices added. `narrow`: the input's angles under 30° between features;
// the triangles at those the output traces are held to them in the last sweeps (improve_shapes).
// `surface`: the input that `projector` projects onto, in the ids of `features`. The vertices of
// `result.mesh` at `guarded` are guarded (VertexSupport): the sweeps check each change there for
// crossings, and no other step moves or removes them (crossing_guard).
void finish_output(RemeshResult& result, const std::vector<Vec3>& seeds,
                   std::size_t optimized_seeds, const std::vector<CellNormal>& cells,
                   const SeedConstraints& constraints, const Features& features,
                   const CurveProjector& curves, const TriangleMesh& surface,
                   const SurfaceProjector& projector, const std::vector<NarrowAngle>& narrow,
                   const RemeshSettings& settings, const std::set<Vec3>& guarded = {});

}  // namespace cvtmesh
