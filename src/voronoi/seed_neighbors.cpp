#include "voronoi/seed_neighbors.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "cvtmesh/errors.hpp"

namespace cvtmesh {

namespace {

// Margins for the rounding of distances computed in floating point, far above it.
constexpr double kRoundedDown = 1 - 1e-9, kRoundedUp = 1 + 1e-9;
// One seed in this many, those that moved most, is checked one by one (bound_by_movers).
constexpr std::size_t kMoversPer = 100;

}  // namespace

void reject_non_finite_seeds(const std::vector<Vec3>& seeds) {
  if (seeds.empty()) throw InvalidArgument("no seeds");
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const Vec3& p = seeds[s];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InvalidArgument("seed " + std::to_string(s) + " has a non-finite coordinate");
  }
}

void reject_identical_seeds(const std::vector<Vec3>& seeds) {
  std::vector<Index> order(seeds.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    return seeds[a] < seeds[b] || (seeds[a] == seeds[b] && a < b);
  });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (seeds[order[k]] == seeds[order[k - 1]])
      throw InvalidArgument("seeds " + std::to_string(order[k - 1]) + " and " +
                            std::to_string(order[k]) + " are identical (remove duplicates)");
}

void sort_by_distance(const std::vector<Vec3>& seeds, Index s, std::span<Index> ids) {
  auto d2 = [&](Index t) { return dot(seeds[t] - seeds[s], seeds[t] - seeds[s]); };
  std::sort(ids.begin(), ids.end(),
            [&](Index a, Index b) { return std::pair(d2(a), a) < std::pair(d2(b), b); });
}

namespace {

// Seed s's k nearest other seeds into `list`, nearest first, and the squared radius within which
// they are all the seeds there are. `near`: scratch. `bound2`: as PointTree::nearest's.
double search_list(const std::vector<Vec3>& seeds, const PointTree& tree, Index s, std::size_t k,
                   std::vector<Index>& near, std::span<Index> list,
                   double bound2 = std::numeric_limits<double>::infinity()) {
  tree.nearest(seeds[s], k + 1, near, bound2);  // s itself is among them: seeds are distinct
  near.erase(std::remove(near.begin(), near.end(), s), near.end());
  near.resize(k);
  sort_by_distance(seeds, s, near);
  std::copy(near.begin(), near.end(), list.begin());
  // Every other seed is at least as far as the last (up to the distances' rounding).
  if (k == 0 || k + 1 >= seeds.size()) return std::numeric_limits<double>::infinity();
  return kRoundedDown * dot(seeds[near[k - 1]] - seeds[s], seeds[near[k - 1]] - seeds[s]);
}

// Within this squared distance of seed s lie at least k other seeds: those of `list`, if it has
// k (rounded up far past the distances' rounding); else infinity.
double bound_from(const std::vector<Vec3>& seeds, Index s, std::span<const Index> list,
                  std::size_t k) {
  if (k == 0 || list.size() < k) return std::numeric_limits<double>::infinity();
  double farthest = 0;
  for (const Index j : list.first(k))
    farthest = std::max(farthest, dot(seeds[j] - seeds[s], seeds[j] - seeds[s]));
  return kRoundedUp * farthest;
}

}  // namespace

SeedNeighbors nearest_neighbors(const std::vector<Vec3>& seeds, const PointTree& tree,
                                std::size_t k, const SeedNeighbors* earlier) {
  k = std::min(k, seeds.size() - 1);
  SeedNeighbors n;
  n.offsets.resize(seeds.size() + 1);
  for (std::size_t s = 0; s <= seeds.size(); ++s) n.offsets[s] = s * k;
  n.ids.resize(seeds.size() * k);
  n.complete2.resize(seeds.size());
  tbb::enumerable_thread_specific<std::vector<Index>> found;
  tbb::parallel_for(
      tbb::blocked_range<Index>(0, static_cast<Index>(seeds.size()), 256), [&](const auto& r) {
        for (Index s = r.begin(); s < r.end(); ++s)
          n.complete2[s] =
              search_list(seeds, tree, s, k, found.local(), std::span(n.ids).subspan(s * k, k),
                          earlier ? bound_from(seeds, s, earlier->of(s), k)
                                  : std::numeric_limits<double>::infinity());
      });
  return n;
}

SeedChanges::SeedChanges(const std::vector<Vec3>& was, const std::vector<Vec3>& seeds)
    : changed_(std::max(was.size(), seeds.size()), 1) {
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    if (s < was.size() && seeds[s] == was[s])
      changed_[s] = 0;
    else
      arrived_.push_back(seeds[s]);
  }
  if (!arrived_.empty()) near_.emplace(arrived_);
}

SeedNeighbors carried_over(const SeedNeighbors& previous, const std::vector<Vec3>& was,
                           const std::vector<Vec3>& seeds, const PointTree& tree, std::size_t k) {
  k = std::min(k, seeds.size() - 1);
  const SeedChanges changes(was, seeds);
  const auto kept = [&](Index j) { return !changes.changed(j); };
  SeedNeighbors n;
  n.offsets.assign(seeds.size() + 1, 0);
  for (Index s = 0; s < seeds.size(); ++s) {
    const std::span<const Index> old =
        changes.changed(s) ? std::span<const Index>{} : previous.of(s);
    n.offsets[s + 1] =
        n.offsets[s] + (changes.changed(s) ? k : std::count_if(old.begin(), old.end(), kept));
  }
  n.ids.resize(n.offsets.back());
  n.complete2.resize(seeds.size());
  tbb::enumerable_thread_specific<std::vector<Index>> found;
  tbb::parallel_for(
      tbb::blocked_range<Index>(0, static_cast<Index>(seeds.size()), 256), [&](const auto& r) {
        for (Index s = r.begin(); s < r.end(); ++s) {
          const std::span<Index> list(n.ids.data() + n.offsets[s], n.ids.data() + n.offsets[s + 1]);
          if (changes.changed(s)) {
            n.complete2[s] = search_list(seeds, tree, s, k, found.local(), list);
            continue;
          }
          // Still nearest first; every seed within the old radius that did not change is there,
          // and a seed that changed is not, so the radius ends at the nearest of those.
          const std::span<const Index> old = previous.of(s);
          std::copy_if(old.begin(), old.end(), list.begin(), kept);
          double c = previous.complete2[s];
          if (const Vec3* a = changes.nearest_arrived(seeds[s]))
            c = std::min(c, kRoundedDown * dot(*a - seeds[s], *a - seeds[s]));
          n.complete2[s] = c;
        }
      });
  return n;
}

MovedLists shrunk_for_moves(SeedNeighbors previous, const std::vector<Vec3>& was,
                            const std::vector<Vec3>& seeds) {
  std::vector<double> move(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s) move[s] = distance(seeds[s], was[s]);
  // The few seeds that moved most (an optimization's step moves some several times as far as
  // nearly all others) are handled one by one, so that the others' radii shrink by the bulk's
  // largest move, not theirs.
  std::vector<double> sorted = move;
  const std::size_t bulk = sorted.size() - 1 - sorted.size() / kMoversPer;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(bulk),
                   sorted.end());
  const double largest = sorted[bulk];
  tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(seeds.size()), 256),
                    [&](const auto& r) {
                      for (Index s = r.begin(); s < r.end(); ++s) {
                        const std::span<Index> ids(previous.ids.data() + previous.offsets[s],
                                                   previous.ids.data() + previous.offsets[s + 1]);
                        sort_by_distance(seeds, s, ids);
                        double& c = previous.complete2[s];
                        if (std::isinf(c)) continue;
                        const double reach = std::sqrt(c) - (move[s] + largest) * kRoundedUp;
                        c = reach > 0 ? kRoundedDown * reach * reach : 0;
                      }
                    });
  return {std::move(previous), std::move(move), largest};
}

SeedNeighbors bound_by_movers(MovedLists moved, const std::vector<Vec3>& seeds,
                              const PointTree& tree) {
  SeedNeighbors& lists = moved.lists;
  // A seed that moved farther than `largest` bounds the radius of every list it is not in by
  // its distance now, where it comes within that radius (serially, in order: the same result
  // on any thread count).
  double reach2 = 0;
  for (const double c : lists.complete2)
    if (!std::isinf(c)) reach2 = std::max(reach2, c);
  std::vector<Index> near;
  for (Index x = 0; x < seeds.size(); ++x) {
    if (!(moved.move[x] > moved.largest)) continue;
    tree.within(seeds[x], reach2, near);
    for (const Index s : near) {
      double& c = lists.complete2[s];
      const std::span<const Index> list = lists.of(s);
      if (s == x || std::find(list.begin(), list.end(), x) != list.end()) continue;
      c = std::min(c, kRoundedDown * dot(seeds[x] - seeds[s], seeds[x] - seeds[s]));
    }
  }
  return std::move(lists);
}

}  // namespace cvtmesh
