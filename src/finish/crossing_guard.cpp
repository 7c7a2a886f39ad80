#include "finish/crossing_guard.hpp"

#include <algorithm>
#include <memory>

#include "geometry/self_crossings.hpp"

namespace cvtmesh {

namespace {

// The crossing triangles of `finished` (crossings_of_its_own) that are not at one of
// `unfinished`'s own (at_crossing): where the extraction already crossed itself, which topology
// control's rounds left, no guard on the finishing steps mends it, and guarding only keeps the
// sweeps from the badly shaped triangles there.
std::vector<Triangle> crossings_made(const TriangleMesh& finished, InputCrossings& input,
                                     const SurfaceProjector* unfinished) {
  std::vector<Triangle> made = crossings_of_its_own(finished, input);
  if (unfinished)
    std::erase_if(
        made, [&](const Triangle& t) { return at_crossing(*unfinished, finished.vertices, t); });
  return made;
}

}  // namespace

void finish_uncrossed(RemeshResult& result, const TriangleMesh& input, const FinishSteps& finish,
                      int attempts, double reach) {
  const RemeshResult unfinished = result;
  finish(result, {});
  InputCrossings input_crossings(input);
  std::vector<Triangle> crossing = crossings_of_its_own(result.mesh, input_crossings);
  result.output_crossing_triangles = crossing.size();
  // Nearly every output: one search of its crossings. Nor where the input crosses itself, as
  // topology control does not refine there either: its output cannot be embedded, and guarding
  // cost camel.off at 5k 0.06% on its Hausdorff max for 4 more crossing triangles in all.
  if (crossing.empty() || input_crossings.found()) return;
  std::unique_ptr<SurfaceProjector> before;
  if (!crossings_of_its_own(unfinished.mesh, input_crossings).empty())
    before = crossing_surface(unfinished.mesh, self_crossing_triangles(unfinished.mesh));
  crossing = crossings_made(result.mesh, input_crossings, before.get());
  std::set<Vec3> guarded;
  for (int attempt = 1; attempt <= attempts && !crossing.empty(); ++attempt) {
    const std::set<Vec3> near =
        points_near_crossings(unfinished.mesh, result.mesh, crossing, reach * attempt);
    guarded.insert(near.begin(), near.end());
    RemeshResult again = unfinished;
    finish(again, guarded);
    std::vector<Triangle> left = crossings_made(again.mesh, input_crossings, before.get());
    if (left.size() >= crossing.size()) break;
    result = std::move(again);
    result.vertices_guarded = guarded.size();
    result.output_crossing_triangles = crossings_of_its_own(result.mesh, input_crossings).size();
    crossing = std::move(left);
  }
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
