// Sheets of a non-manifold input, remeshed apart (remesh/by_component), meet again along the
// input's edges of three or more triangles. Each sheet keeps such an edge as a feature, its ends
// as corners, but may put vertices along it where another sheet puts none, or elsewhere: zipping
// gives every sheet the vertices of all, so that welding equal positions joins them edge to edge.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "features/edge_uses.hpp"

namespace cvtmesh {

// One sheet's output inside the whole's: its vertices are [first, end).
struct SheetVertices {
  Index first = 0, end = 0;
};

// A stretch of the input where sheets meet, from corner to corner, and the sheets (indices into
// the SheetVertices) that have it.
struct SharedSegment {
  std::vector<Vec3> points;
  std::vector<std::size_t> sheets;
};

// Per stretch, each sheet's vertices on it (within a round-off of it, its ends among
// them) must run from a to b as a chain of the output's edges; every position on it that some
// sheet has and another lacks is added to the other, splitting its triangles on that edge.
// Returns, per position added or found inside a segment, the sheets' vertices there as (key,
// output vertex) pairs, a key per position from `first_key` up; none when a sheet's chain is
// broken (a sheet missing an end, or a step of it no edge of the output), and `mesh` is then
// unusable. Vertices added go at the end of mesh.vertices, outside every sheet's range; a
// feature edge split is replaced by its halves in `feature_edges`.
std::optional<std::vector<std::pair<Index, Index>>> zip_shared_segments(
    TriangleMesh& mesh, std::vector<Edge>& feature_edges, const std::vector<SheetVertices>& sheets,
    const std::vector<SharedSegment>& segments, Index first_key);

}  // namespace cvtmesh
