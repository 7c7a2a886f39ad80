// Where sheets of a non-manifold input meet (edges of three or more triangles), each sheet is
// remeshed on its own (remesh/by_component), and the sheets' outputs must have the same vertices
// along the junction to be welded there. Sheets that each placed their own curve seeds would put
// them a hair apart (triple_vierbein.obj: slivers of 0.001° where they were zipped), so the
// junction's vertices are chosen once, for all: each junction curve resampled at the spacing,
// the points inserted into the input, and every sheet keeps them as corners.
#pragma once

#include <vector>

#include "cvtmesh/mesh.hpp"
#include "features/edge_uses.hpp"

namespace cvtmesh {

struct BranchCurves {
  TriangleMesh mesh;           // the input, its junction edges split at the points chosen
  std::vector<bool> corner;    // per vertex of `mesh`: a junction vertex every sheet keeps
  std::vector<bool> on_curve;  // per vertex of `mesh`: on a junction curve
  std::vector<Edge> split;     // the input's edges that were split, sorted
  std::vector<std::vector<Index>> pieces;  // per edge split: its vertices from its first end
  struct Added {
    Index a, b;  // the input edge it splits, a < b
    double t;    // where: a + t (b - a)
  };
  std::vector<Added> added;  // per vertex added, in order (after the input's)
  // The junction's stretches from corner to corner, as vertices of `mesh` (a closed one ends
  // where it starts).
  std::vector<std::vector<Index>> stretches;
};

// Each curve of the junction (its edges chained between vertices where one, or three or more,
// junction edges meet; a closed one from its smallest vertex) gets points evenly spaced about
// `spacing` apart between its corners (its ends, and where it turns or sheets join or leave it);
// a point within a thousandth of a step of an input vertex is that vertex. Nothing changes for an
// input without junction edges.
BranchCurves resample_branch_curves(const TriangleMesh& mesh, double spacing);

// The edges of `output` with three or more triangles that do not run along the junction: no
// stretch has both their ends (to a round-off), and their middle is off it. Such an edge is one
// a remesh added where its sheets met beside the junction, or across a bend of it.
std::size_t edges_off_junction(const TriangleMesh& output, const BranchCurves& junction);

}  // namespace cvtmesh
