// A triangle with an obtuse angle at a boundary vertex (a boundary corner of about 110° in one
// triangle, its two boundary edges fixing the angle, or such a corner's wider triangle of two)
// stays obtuse whatever flips and moves do: no flip takes a boundary edge, and a corner does not
// move. Halving the triangle's edge across from the corner gives the corner one triangle more,
// which the shape sweeps then even out with their neighbours (issue 18 item 6: blobby_3cc.off at
// 1k had its worst triangle there, Q 0.513).
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"
#include "features/curve_projector.hpp"
#include "finish/improve_shapes.hpp"

namespace cvtmesh {

class SurfaceProjector;

// Which obtuse corners split_obtuse_corners halves across from.
enum class ObtuseCorners {
  at_boundary,  // at a boundary vertex, which no flip or move opens up
  under_bar,    // at any vertex, in a triangle under the bar's Q (those the shape sweeps left)
};

// Where the edge across an obtuse corner is a feature edge, a flip cannot take it either: a
// vertex just off a crease, or off a boundary, facing one of its long edges (mech-holes-shark.off
// at 2k and 5k had its worst triangles so, 127-130°). `along` lets such an edge be halved too, its
// middle put on its curve: the curve of its vertices in `supports` (per vertex of the mesh), the
// new vertex appended there as a vertex of that curve, and the edge replaced by its halves in
// `feature_edges` (sorted).
struct CurveSplits {
  const CurveProjector& curves;
  std::vector<VertexSupport>& supports;
  std::vector<Edge>& feature_edges;
};

// For each triangle with an angle over 100° at a corner of `which` kind, halves the edge across
// from it where that edge has two triangles, used in opposite directions, and is no feature edge
// (`features`, sorted) and its middle lies within a quarter of its length of `surface`: the
// nearest point there is appended to the vertices, and the two triangles become four, in their
// orientation. With `along`, a feature edge of two triangles or one (a boundary edge) is halved
// as well where its middle's foot on its curve lies that near: its triangles become twice as
// many. With `narrow_at` (per vertex, the narrow input angle there, 0 where none:
// narrow_angle_at_vertices, as bar_shapes has it), a triangle with such a vertex is left alone: it
// is held to its input angle, not to the bar (fandisk.off adaptive at 2k: halving there took Q at
// its 19.4° angle from 0.363 to 0.313). A triangle is split once at most. Returns the vertices
// added.
std::size_t split_obtuse_corners(TriangleMesh& mesh, const std::vector<Edge>& features,
                                 const SurfaceProjector& surface,
                                 ObtuseCorners which = ObtuseCorners::at_boundary,
                                 CurveSplits* along = nullptr,
                                 const std::vector<double>* narrow_at = nullptr);

}  // namespace cvtmesh
