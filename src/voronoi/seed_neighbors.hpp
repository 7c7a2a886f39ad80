// Candidate Voronoi neighbours of the seeds: each seed's k nearest seeds (kd-tree). The RVD
// clips with them under a security radius: a bisector can cut a polygon only if its seed lies
// within twice the polygon's distance from the cell's seed, so a list that reaches farther
// than that holds every neighbour that matters, and a radius search completes one that does
// not. No Delaunay triangulation is needed, and none of its degenerate cases arise.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "geometry/point_tree.hpp"

namespace cvtmesh {

// Compressed adjacency: the candidates of seed s are ids[offsets[s] .. offsets[s+1]), nearest
// first (ties by id), so that clipping can stop at the first bisector too far away.
struct SeedNeighbors {
  std::vector<std::size_t> offsets;
  std::vector<Index> ids;
  // Per seed, a squared distance within which its list holds every other seed (infinite when
  // it holds them all): beyond the last candidate a bisector may still matter, and a radius
  // search finds the rest.
  std::vector<double> complete2;

  std::span<const Index> of(Index s) const {
    return {ids.data() + offsets[s], ids.data() + offsets[s + 1]};
  }
};

// Throws InvalidArgument for no seeds or a non-finite seed (naming the first).
void reject_non_finite_seeds(const std::vector<Vec3>& seeds);
// Throws InvalidArgument for identical seeds (naming the first pair).
void reject_identical_seeds(const std::vector<Vec3>& seeds);

// Each seed's k nearest other seeds (fewer when there are fewer seeds). `earlier`, if given, holds
// lists of other seeds (any k of a list bound how far its seed's search must look: an earlier
// evaluation's lists for the seeds as they are now), which prune the searches from their start.
SeedNeighbors nearest_neighbors(const std::vector<Vec3>& seeds, const PointTree& tree,
                                std::size_t k, const SeedNeighbors* earlier = nullptr);

// Which of `seeds` differ from the seeds at `was` (moved, or came: an id past `was`; ids past
// `seeds` went), and the nearest of those that moved or came to a point.
class SeedChanges {
 public:
  SeedChanges(const std::vector<Vec3>& was, const std::vector<Vec3>& seeds);
  SeedChanges(const SeedChanges&) = delete;  // the tree refers to `arrived_`
  SeedChanges& operator=(const SeedChanges&) = delete;
  bool changed(Index s) const { return changed_[s] != 0; }
  // Where the seed that moved or came nearest to p now is; null if none did.
  const Vec3* nearest_arrived(const Vec3& p) const {
    return near_ ? &arrived_[(*near_)(p)] : nullptr;
  }

 private:
  std::vector<char> changed_;  // per id of either
  std::vector<Vec3> arrived_;
  std::optional<PointTree> near_;
};

// The lists of `previous`, made for the seeds at `was`, for `seeds` of which only some moved,
// came or went, as between the triangulations of polishing and topology control: a seed that did
// not change keeps its list without the seeds that did, its complete radius bounded by the
// nearest of those as they are now; the others get k nearest seeds from `tree`, which holds
// `seeds`.
SeedNeighbors carried_over(const SeedNeighbors& previous, const std::vector<Vec3>& was,
                           const std::vector<Vec3>& seeds, const PointTree& tree, std::size_t k);

// The lists of `previous`, made for the seeds at `was`, for the same seeds now at `seeds` (issue
// 19: seeds that moved little since keep their candidates, and no kNN search is needed): each
// re-sorted by distance, its complete radius shrunk by its seed's move plus the largest move
// of all but the 1% that moved most (a seed outside a list was at least that far from it, and
// both have moved since), and then (bound_by_movers) by the distance now of each of those 1%
// outside it. In two steps: the first needs no kd-tree, so it runs while one is built.
struct MovedLists {
  SeedNeighbors lists;
  std::vector<double> move;  // per seed, how far it moved
  double largest = 0;        // the largest move of all but the 1% that moved most
};
MovedLists shrunk_for_moves(SeedNeighbors previous, const std::vector<Vec3>& was,
                            const std::vector<Vec3>& seeds);
// `tree` holds `seeds`.
SeedNeighbors bound_by_movers(MovedLists moved, const std::vector<Vec3>& seeds,
                              const PointTree& tree);

// Sorts seed ids by squared distance to seed s, ties by id.
void sort_by_distance(const std::vector<Vec3>& seeds, Index s, std::span<Index> ids);

}  // namespace cvtmesh
