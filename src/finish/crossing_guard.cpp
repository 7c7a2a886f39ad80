#include "finish/crossing_guard.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <optional>

#include "cvtmesh/topology.hpp"
#include "geometry/self_crossings.hpp"

namespace cvtmesh {

namespace {

// Of `crossing` (triangles of `finished`), those not at one of `unfinished`'s own crossings
// (at_crossing; `unfinished`: the extraction's crossings of its own, crossings_of_its_own): where
// the extraction already crossed itself, which topology control's rounds left, no guard on the
// finishing steps mends it, and guarding only keeps the sweeps from the badly shaped triangles
// there. Not its crossings at the input's, which shield nothing: they reach past the input's
// as far as the extraction's triangles are larger (a fuzzed man.off with 3% of its edges split,
// at 1.5k: 4 crossing triangles made by the sweeps beside them, none guarded).
std::vector<Triangle> crossings_made(std::vector<Triangle> crossing, const TriangleMesh& finished,
                                     const SurfaceProjector* unfinished) {
  if (unfinished)
    std::erase_if(crossing, [&](const Triangle& t) {
      return at_crossing(*unfinished, finished.vertices, t);
    });
  return crossing;
}

// Whether each of `triangles` (of `finished`) is a triangle of `unfinished`, its corners where
// they were.
bool as_extracted(const std::vector<Triangle>& triangles, const TriangleMesh& finished,
                  const TriangleMesh& unfinished) {
  using Corners = std::array<Vec3, 3>;
  const auto corners = [](const TriangleMesh& mesh, const Triangle& t) {
    Corners c{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    std::sort(c.begin(), c.end());
    return c;
  };
  std::set<Corners> extracted;
  for (const Triangle& t : unfinished.triangles) extracted.insert(corners(unfinished, t));
  return std::all_of(triangles.begin(), triangles.end(),
                     [&](const Triangle& t) { return extracted.contains(corners(finished, t)); });
}

}  // namespace

std::optional<RemeshResult> finish_uncrossed(RemeshResult& result, InputCrossings& input_crossings,
                                             const FinishSteps& finish, int attempts,
                                             double reach) {
  const RemeshResult unfinished = result;
  finish(result, {});
  std::vector<Triangle> crossing = crossings_of_its_own(result.mesh, input_crossings);
  result.output_crossing_triangles = crossing.size();
  // Nearly every output: one search of its crossings. Where the input crosses itself, the
  // output's crossings there are not its own (crossings_of_its_own); those the finishing steps
  // made elsewhere are guarded as on any input (man.off at 1k, 5k and 10k: 8, 21 and 26 crossing
  // triangles away from its input's 776, then none).
  // An output without the input's topology is no valid one, guarded or not: no attempt for it
  // (blade.off with 161 one-triangle holes, slivers far narrower than the spacing, at 4k: its
  // first two tries of topology_first, each crossing itself at 700 triangles, took 92 s and 113 s
  // guarded, 30 s and 31 s not).
  // (The finishing steps keep the topology: the extraction's is the output's.)
  if (crossing.empty() || !keeps_topology(analyze_topology(unfinished.mesh), result.input_topology))
    return std::nullopt;
  std::vector<Triangle> own = std::move(crossing);  // the output's crossings of its own
  const std::unique_ptr<SurfaceProjector> before = crossing_surface(
      unfinished.mesh.vertices, crossings_of_its_own(unfinished.mesh, input_crossings));
  std::set<Vec3> guarded;
  std::optional<RemeshResult> unguarded;  // the first output, once a guarded one replaces it
  // Where crossings are left, the first output too, for what comes after (see the header).
  const auto left_to_mend = [&] {
    return result.output_crossing_triangles > 0 ? std::move(unguarded) : std::nullopt;
  };
  // The steps run again with the vertices near the crossings `counted` picks of the output's own
  // guarded, within `reach` times the attempt's number, while each run leaves fewer of those and
  // no more of its own in all (camel.off at 5k, its input crossing itself: guarded, fewer made
  // but 29 of its own where there were 25, and the Hausdorff max 0.507% -> 0.571%). With `widen`,
  // an attempt that does not help is passed over for the next, wider one: a guard too narrow may
  // leave the sweeps a fold just outside it (a fuzzed dino.off at 300: 7 vertices guarded left 4
  // crossing triangles, 11 none); else the attempts stop there. An attempt whose guard adds no
  // vertex to the last run's (the same run again) is passed over. Returns the crossings it picks
  // that are left.
  const auto guard_around = [&](const auto& counted, bool widen) {
    std::vector<Triangle> targets = counted(own, result.mesh);
    // The size of the last run's guard, which grows with the reach until a run is kept.
    std::size_t last_run = guarded.size();
    for (int attempt = 1; attempt <= attempts && !targets.empty(); ++attempt) {
      std::set<Vec3> more = guarded;
      more.merge(points_near_crossings(unfinished.mesh, result.mesh, targets, reach * attempt));
      if (more.size() == last_run) continue;
      last_run = more.size();
      RemeshResult again = unfinished;
      finish(again, more);
      std::vector<Triangle> all = crossings_of_its_own(again.mesh, input_crossings);
      std::vector<Triangle> left = counted(all, again.mesh);
      if (left.size() >= targets.size() || all.size() > own.size()) {
        if (widen) continue;
        break;
      }
      if (!unguarded) unguarded = std::move(result);
      result = std::move(again);
      guarded = std::move(more);
      result.vertices_guarded = guarded.size();
      result.output_crossing_triangles = all.size();
      own = std::move(all);
      targets = std::move(left);
    }
    return targets;
  };
  // First those the steps made, away from the extraction's own crossings: a guard wide enough
  // checks every step that made them.
  const std::vector<Triangle> made = guard_around(
      [&](std::vector<Triangle> all, const TriangleMesh& mesh) {
        return crossings_made(std::move(all), mesh, before.get());
      },
      true);
  // Then all of the output's own crossings that are left, those at the extraction's own too: the
  // steps before the sweeps may mend those, for the sweeps to cross there again (a fuzzed
  // ChineseDragon-10kv.off, a soup with a tenth of its triangles turned, adaptive at 300: 3
  // crossing triangles, none guarded). Kept only where fewer are left in all, so that where the
  // extraction's own crossings stay whatever the steps do, the sweeps keep their room there.
  // Not where none is left there (all were tried above), nor where each is a triangle of the
  // extraction that the steps left as it was: no guard changes those (a fuzzed
  // ChineseDragon-10kv with noise and dropouts at 300: its run again gave the same output). No
  // wider attempt after one that does not help: where the extraction's own crossings stay, wider
  // guards seldom do better, and each costs a run of the steps (a fuzzed bull.off, adaptive at
  // 300: three attempts, 70 to 98 vertices guarded, each left the same 6).
  if (made.size() == own.size() || as_extracted(own, result.mesh, unfinished.mesh))
    return left_to_mend();
  guard_around([](std::vector<Triangle> all, const TriangleMesh&) { return all; }, false);
  return left_to_mend();
}

std::set<Vec3> points_near_crossings(const TriangleMesh& unfinished, const TriangleMesh& finished,
                                     const std::vector<Triangle>& crossing, double reach) {
  std::set<Vec3> near;
  for (const Triangle& t : crossing) {
    const Vec3 &a = finished.vertices[t[0]], &b = finished.vertices[t[1]],
               &c = finished.vertices[t[2]];
    const Vec3 centre = (1.0 / 3) * (a + b + c);
    const double r = reach * std::max({distance(a, b), distance(b, c), distance(c, a)});
    // Crossings are few where there are any (none on most outputs): a pass over the vertices
    // for each costs less than a search structure.
    for (const Vec3& p : unfinished.vertices)
      if (distance(p, centre) <= r) near.insert(p);
  }
  return near;
}

}  // namespace cvtmesh
