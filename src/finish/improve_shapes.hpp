// The output's last touch (issue 18, item 6): the restricted Delaunay triangulation of seeds that
// an iteration cap stopped short of a centroidal tessellation, or that topology control added at
// details finer than the spacing, has a few badly shaped triangles left. Around them, this step
// flips edges between triangles that fold little and moves vertices towards the centre of their
// star, back onto the input surface, as tangential relaxation does in CGAL's and pmp-library's
// remeshers, then searches around each vertex still at a bad triangle for a better place (on the
// surface, or along its feature curve for a vertex that traces one). Once that changes nothing,
// flips that bring valences nearer 6, each with moves around it, mend what neither can alone: a
// vertex of valence 4 beside ones of 8; where no flip does, the shortest edge of a badly shaped
// triangle collapses (a vertex merged into its neighbour, then moves around it): crowded seeds.
// None of them changes the triangulation's topology (a flip never makes an edge that is there
// already, a move changes no connectivity, a collapse keeps the link condition), so a manifold
// stays a manifold with the same Euler characteristic and boundary loops, and a change is kept
// only when the worst triangle it touches gets better.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

class CurveProjector;
class SurfaceProjector;

// Where a vertex may go: anywhere on the surface, along one feature curve (keeping the curve's
// edges on the curve), or nowhere (corners, vertices of features that could not be traced).
struct VertexSupport {
  enum class Kind : std::uint8_t { surface, curve, fixed };
  Kind kind = Kind::surface;
  std::uint32_t curve = 0;  // for Kind::curve: its index in the CurveProjector
  // Every change here is also checked for triangles that pass through others (finish/
  // crossing_guard: where the finishing steps made the output cross itself before).
  bool guarded = false;
};

struct ShapeImprovement {
  std::size_t flips = 0;      // edges flipped
  std::size_t moves = 0;      // vertex moves kept
  std::size_t collapses = 0;  // short edges collapsed (their surface vertex left unused)
  std::size_t searches = 0;   // searches for a better place for a vertex
};

// Improves the triangles of `mesh` with θmin under 40° or Q under 0.7 (a little above what a
// converged CVT gives on a smooth surface), in `sweeps` sweeps at most in each of two passes
// (below). `support` (per vertex; missing ones are surface vertices) says where each may go:
// surface vertices go to their nearest point on `surface`, curve vertices stay on their curve of
// `curves` (needed when any vertex is a curve vertex), if one or two feature edges meet there.
// Vertices on boundary or non-manifold edges, other than curve vertices on a boundary between their
// two feature edges, and tips of the surface (angle defect over 30°; curve vertices excepted),
// never move; saddles (under -30°) move only in a second pass, once the first, with them held too,
// has done what it can. `feature_edges` (sorted) never flip, and of the others only those with
// exactly two triangles, which use them in opposite directions. A collapse takes one surface
// vertex, or a curve vertex along its curve (`feature_edges` then run from the vertex it merged
// into), out of the triangles, leaving it unused; at most one vertex in 100 goes so. Each change
// keeps the triangles it touches about as close to the surface as they were, and at a guarded
// vertex, passes none of them through another triangle. Sequential, in a fixed
// order: the result does not depend on the thread count. `narrow_at` (per vertex; missing ones 0)
// gives the input angle under 30° of a tip the output traces at that vertex: a triangle there is
// judged by its smallest angle against that angle, as the quality promise judges it (issue 18
// item 6), not against 60°, so that lifting it, which the input's angle bounds, never pays for a
// worse triangle beside it. `active` (per vertex; empty: all) limits the work to the triangles
// with an active vertex, and the moves to active vertices.
ShapeImprovement improve_shapes(TriangleMesh& mesh, const SurfaceProjector& surface,
                                const CurveProjector* curves, std::vector<VertexSupport> support,
                                std::vector<Edge>& feature_edges, int sweeps,
                                const std::vector<double>& narrow_at = {},
                                std::vector<bool> active = {});

}  // namespace cvtmesh
