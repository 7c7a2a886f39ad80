// Where the finishing steps make the output pass through itself, they run again with the
// vertices there guarded (finish/crossing_guard).
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>

#include "cvtmesh/topology.hpp"
#include "finish/crossing_guard.hpp"
#include "geometry/self_crossings.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using testing::crossing_planes;
using testing::mapped_grid;

std::size_t crossing_triangles(const TriangleMesh& mesh) {
  const std::vector<bool> crossing = self_crossing_triangles(mesh);
  return static_cast<std::size_t>(std::count(crossing.begin(), crossing.end(), true));
}

// The unit square in 8 × 8 cells; its vertex 40 is at (0.5, 0.5).
TriangleMesh grid() {
  return mapped_grid(8, 8, [](double u, double v) { return Vec3{u, v, 0}; });
}
constexpr Index kCentre = 40;

// `mesh` with vertex `v` moved 2.4 cells along x, past its neighbours: its triangles fold over
// theirs.
TriangleMesh folded(TriangleMesh mesh, Index v) {
  mesh.vertices[v] += Vec3{0.3, 0, 0};
  return mesh;
}

// Finishing steps that fold the centre, unless `spared` (where given) is guarded, counting their
// runs in `runs`.
FinishSteps folding_centre(int& runs, std::optional<Vec3> spared = std::nullopt) {
  return [&runs, spared](RemeshResult& r, const std::set<Vec3>& guarded) {
    ++runs;
    if (!spared || !guarded.contains(*spared)) r.mesh = folded(r.mesh, kCentre);
  };
}

// finish_uncrossed, as the pipeline calls it, on an extraction of `input`; what it returns to
// `unguarded`, if given.
RemeshResult finished(const TriangleMesh& extraction, const TriangleMesh& input,
                      const FinishSteps& finish, std::optional<RemeshResult>* unguarded = nullptr) {
  RemeshResult result;
  result.mesh = extraction;
  result.input_topology = analyze_topology(input);
  InputCrossings crossings(input);
  std::optional<RemeshResult> first = finish_uncrossed(result, crossings, finish, 3, 1.5);
  if (unguarded) *unguarded = std::move(first);
  return result;
}

TEST(CrossingGuard, StepsThatFoldTheOutputRunAgainWithTheVerticesThereGuarded) {
  const TriangleMesh input = grid();
  ASSERT_EQ(input.vertices[kCentre], (Vec3{0.5, 0.5, 0}));
  ASSERT_GT(crossing_triangles(folded(input, kCentre)), 0u);
  RemeshResult result;
  result.mesh = input;
  result.input_topology = analyze_topology(input);
  int runs = 0;
  std::size_t guarded_last = 0;
  // A step that folds the centre unless it is guarded.
  const FinishSteps fold = [&](RemeshResult& r, const std::set<Vec3>& guarded) {
    ++runs;
    guarded_last = guarded.size();
    if (!guarded.contains(input.vertices[kCentre])) r.mesh = folded(r.mesh, kCentre);
  };
  InputCrossings crossings(input);
  // None is left: no first output comes back for a later mend.
  EXPECT_FALSE(finish_uncrossed(result, crossings, fold, 3, 1.5).has_value());
  EXPECT_EQ(runs, 2);
  EXPECT_EQ(result.output_crossing_triangles, 0u);
  EXPECT_EQ(result.vertices_guarded, guarded_last);
  EXPECT_GT(result.vertices_guarded, 0u);
  EXPECT_EQ(result.mesh.vertices, input.vertices);
}

TEST(CrossingGuard, WhereGuardingDoesNotHelpTheFirstOutputStaysAndItsCrossingsAreCounted) {
  const TriangleMesh input = grid();
  int runs = 0;
  // Folds the centre whatever is guarded: the attempts, wider each time, are no better. The
  // second guards the whole grid, so the third, guarding no vertex more, is passed over.
  std::size_t guarded_last = 0;
  const FinishSteps fold = [&](RemeshResult& r, const std::set<Vec3>& guarded) {
    guarded_last = guarded.size();
    folding_centre(runs)(r, guarded);
  };
  std::optional<RemeshResult> unguarded;
  const RemeshResult result = finished(input, input, fold, &unguarded);
  EXPECT_EQ(runs, 3);
  EXPECT_EQ(guarded_last, input.vertices.size());
  EXPECT_EQ(result.output_crossing_triangles, crossing_triangles(folded(input, kCentre)));
  EXPECT_EQ(result.vertices_guarded, 0u);
  // No guarded output was kept: the output is the first one, and nothing else comes back.
  EXPECT_FALSE(unguarded.has_value());
}

// The vertex of `mesh` at `p`.
Index vertex_at(const TriangleMesh& mesh, const Vec3& p) {
  const auto at = std::find(mesh.vertices.begin(), mesh.vertices.end(), p);
  return static_cast<Index>(at - mesh.vertices.begin());
}

TEST(CrossingGuard, AGuardTooNarrowIsWidenedWhereTheFoldMovesPastIt) {
  // [0, 2]² in cells of 1/8. Steps that fold the centre (1, 1) unguarded, a vertex 0.75 away,
  // (1.75, 1), under a guard no wider than the first attempt's, and nothing under a wider one: a
  // guard too narrow leaves the sweeps a fold just outside it (a fuzzed dino.off at 300).
  const TriangleMesh input = mapped_grid(16, 16, [](double u, double v) {
    return Vec3{2 * u, 2 * v, 0};
  });
  const Index centre = vertex_at(input, {1, 1, 0}), beyond = vertex_at(input, {1.75, 1, 0});
  ASSERT_LT(std::max(centre, beyond), input.vertices.size());
  const TriangleMesh centre_fold = folded(input, centre), beyond_fold = folded(input, beyond);
  InputCrossings none(input);
  const std::vector<Triangle> targets = crossings_of_its_own(centre_fold, none);
  const std::size_t first_guard = points_near_crossings(input, centre_fold, targets, 1.5).size();
  ASSERT_GT(points_near_crossings(input, centre_fold, targets, 3.0).size(), first_guard);
  // The moved vertex lies past the first attempt's reach.
  ASSERT_FALSE(points_near_crossings(beyond_fold, centre_fold, targets, 1.5)
                   .contains(beyond_fold.vertices[beyond]));
  int runs = 0;
  const FinishSteps steps = [&](RemeshResult& r, const std::set<Vec3>& guarded) {
    ++runs;
    if (guarded.empty())
      r.mesh = centre_fold;
    else if (guarded.size() <= first_guard)
      r.mesh = beyond_fold;
  };
  const RemeshResult result = finished(input, input, steps);
  EXPECT_EQ(runs, 3);
  EXPECT_EQ(result.output_crossing_triangles, 0u);
  EXPECT_GT(result.vertices_guarded, first_guard);
  EXPECT_EQ(result.mesh.vertices, input.vertices);
}

TEST(CrossingGuard, WhereAGuardedOutputIsKeptAndCrossingsAreLeftTheFirstOutputIsReturned) {
  // Steps that fold vertex 10, (1/4, 1/8), whatever is guarded, and the centre unless it is: the
  // guard mends the centre's fold and is kept, and the fold at vertex 10 is left. The first,
  // unguarded output comes back too, for the halving that comes after (finish/split_crossings),
  // which may do better on it.
  const TriangleMesh input = grid();
  constexpr Index kStubborn = 10;
  const TriangleMesh one = folded(input, kStubborn), both = folded(one, kCentre);
  ASSERT_GT(crossing_triangles(both), crossing_triangles(one));
  ASSERT_GT(crossing_triangles(one), 0u);
  const FinishSteps steps = [&](RemeshResult& r, const std::set<Vec3>& guarded) {
    r.mesh = guarded.contains(input.vertices[kCentre]) ? one : both;
  };
  std::optional<RemeshResult> unguarded;
  const RemeshResult result = finished(input, input, steps, &unguarded);
  EXPECT_EQ(result.mesh.vertices, one.vertices);
  EXPECT_EQ(result.output_crossing_triangles, crossing_triangles(one));
  EXPECT_GT(result.vertices_guarded, 0u);
  ASSERT_TRUE(unguarded.has_value());
  EXPECT_EQ(unguarded->mesh.vertices, both.vertices);
  EXPECT_EQ(unguarded->output_crossing_triangles, crossing_triangles(both));
  EXPECT_EQ(unguarded->vertices_guarded, 0u);
}

TEST(CrossingGuard, WhereTheInputOrTheExtractionCrossesItselfThereNothingRunsAgain) {
  const TriangleMesh plain = grid(), crossing = folded(plain, kCentre);
  const FinishSteps nothing = [](RemeshResult&, const std::set<Vec3>&) {};
  int runs = 0;
  const FinishSteps counted = [&](RemeshResult& r, const std::set<Vec3>& g) {
    ++runs;
    nothing(r, g);
  };
  // The input crosses itself there: so does its output, and that is no crossing of its own.
  const RemeshResult of_input = finished(crossing, crossing, counted);
  EXPECT_EQ(runs, 1);
  EXPECT_EQ(of_input.output_crossing_triangles, 0u);
  // The extraction crossed itself (topology control's rounds left it), and the steps left its
  // crossing triangles as they were, which no guard changes: counted, not guarded.
  runs = 0;
  const RemeshResult of_extraction = finished(crossing, plain, counted);
  EXPECT_EQ(runs, 1);
  EXPECT_EQ(of_extraction.output_crossing_triangles, crossing_triangles(crossing));
  EXPECT_EQ(of_extraction.vertices_guarded, 0u);
}

TEST(CrossingGuard, CrossingsAtTheExtractionsOwnThatTheStepsMendAndMakeAgainRunAgain) {
  // The extraction is folded at the centre. Steps that unfold it, then fold the centre's
  // neighbour unless it is guarded: their crossings lie at the extraction's own, which shield
  // them from the first attempts (crossings_made), and guarding them leaves none.
  const TriangleMesh plain = grid(), extraction = folded(plain, kCentre);
  constexpr Index kNeighbour = kCentre + 1;
  int runs = 0;
  const FinishSteps mend_then_fold = [&](RemeshResult& r, const std::set<Vec3>& guarded) {
    ++runs;
    r.mesh = guarded.contains(plain.vertices[kNeighbour]) ? plain : folded(plain, kNeighbour);
  };
  const RemeshResult result = finished(extraction, plain, mend_then_fold);
  EXPECT_EQ(runs, 2);
  EXPECT_EQ(result.output_crossing_triangles, 0u);
  EXPECT_GT(result.vertices_guarded, 0u);
  EXPECT_EQ(result.mesh.vertices, plain.vertices);
}

TEST(CrossingGuard, AtTheExtractionsOwnCrossingsAnAttemptThatDoesNotHelpIsTheLast) {
  // As above, but the steps fold the neighbour whatever is guarded: at the extraction's own
  // crossings no wider attempt follows one that does not help (each costs a run of the steps).
  const TriangleMesh plain = grid(), extraction = folded(plain, kCentre);
  const TriangleMesh refolded = folded(plain, kCentre + 1);
  int runs = 0;
  const FinishSteps mend_then_fold = [&](RemeshResult& r, const std::set<Vec3>&) {
    ++runs;
    r.mesh = refolded;
  };
  const RemeshResult result = finished(extraction, plain, mend_then_fold);
  EXPECT_EQ(runs, 2);
  EXPECT_EQ(result.output_crossing_triangles, crossing_triangles(refolded));
  EXPECT_EQ(result.vertices_guarded, 0u);
}

TEST(CrossingGuard, WhereTheInputCrossesItselfElsewhereTheCrossingsMadeAreGuarded) {
  // The input folded at vertex 10, (1/8, 1/8); the steps fold the centre unless it is guarded:
  // crossings farther from the input's than their longest edges are the output's own.
  const TriangleMesh plain = grid(), input = folded(plain, 10);
  ASSERT_GT(crossing_triangles(input), 0u);
  int runs = 0;
  const RemeshResult beside_input =
      finished(plain, input, folding_centre(runs, plain.vertices[kCentre]));
  EXPECT_EQ(runs, 2);
  EXPECT_EQ(beside_input.output_crossing_triangles, 0u);
  EXPECT_GT(beside_input.vertices_guarded, 0u);
  EXPECT_EQ(beside_input.mesh.vertices, plain.vertices);
  // Where guarding leaves as many of its own in all, the first output stays (three attempts).
  runs = 0;
  const RemeshResult unhelped = finished(plain, input, folding_centre(runs));
  EXPECT_EQ(runs, 4);
  EXPECT_GT(unhelped.output_crossing_triangles, 0u);
  EXPECT_EQ(unhelped.vertices_guarded, 0u);
}

TEST(CrossingGuard, CrossingsMadeBesideTheExtractionsCrossingsAtTheInputsRunAgain) {
  // The input: the planes z = 0 and x = 0, each in three strips, crossing along the y axis; its
  // crossing triangles, the middle strips, are 0.02 wide. The extraction: the same planes, two
  // triangles each, crossing there too, its crossing triangles covering the planes.
  const TriangleMesh input = crossing_planes({-1, -0.01, 0.01, 1});
  const TriangleMesh extraction = crossing_planes({-1, 1});
  // Steps that add two small triangles passing through each other 0.05 above z = 0, 0.9 from the
  // input's crossing and 0.15 from the extraction's corner (1, 1, 0): crossings of the output's
  // own, made by the steps, within their longest edge of the extraction's crossing triangles.
  int runs = 0;
  std::set<Vec3> last_guard;
  const FinishSteps crossing_pair = [&](RemeshResult& r, const std::set<Vec3>& guarded) {
    ++runs;
    last_guard = guarded;
    const auto first = static_cast<Index>(r.mesh.vertices.size());
    for (const Vec3& p : {Vec3{0.85, 0.85, 0.05}, Vec3{0.95, 0.85, 0.05}, Vec3{0.9, 0.95, 0.05},
                          Vec3{0.9, 0.87, 0.02}, Vec3{0.9, 0.87, 0.08}, Vec3{0.9, 0.93, 0.05}})
      r.mesh.vertices.push_back(p);
    r.mesh.triangles.push_back({first, first + 1, first + 2});
    r.mesh.triangles.push_back({first + 3, first + 4, first + 5});
  };
  const RemeshResult result = finished(extraction, input, crossing_pair);
  // They are run again with the corner guarded; the wider attempts guard no vertex more and are
  // passed over; the steps cross again whatever is guarded, so the first output stays.
  EXPECT_EQ(runs, 2);
  EXPECT_EQ(last_guard, (std::set<Vec3>{{1, 1, 0}}));
  EXPECT_EQ(result.output_crossing_triangles, 2u);
  EXPECT_EQ(result.vertices_guarded, 0u);
}

TEST(CrossingGuard, AnExtractionWithoutTheInputsTopologyIsNotGuarded) {
  // The extraction has a hole that the input does not, away from the centre (a triangle of the
  // cell from (3/8, 1/8) to (1/2, 1/4) gone): no attempt, its crossings counted.
  const TriangleMesh input = grid();
  TriangleMesh holed = input;
  const auto centroid = [&](const Triangle& t) {
    return (1.0 / 3) * (holed.vertices[t[0]] + holed.vertices[t[1]] + holed.vertices[t[2]]);
  };
  const Vec3 cell_centre{0.4375, 0.1875, 0};
  const auto far_triangle = std::min_element(
      holed.triangles.begin(), holed.triangles.end(), [&](const Triangle& a, const Triangle& b) {
        return distance(centroid(a), cell_centre) < distance(centroid(b), cell_centre);
      });
  ASSERT_LT(distance(centroid(*far_triangle), cell_centre), 0.0625);
  holed.triangles.erase(far_triangle);
  int runs = 0;
  const Vec3 centre = input.vertices[kCentre];
  const RemeshResult result = finished(holed, input, folding_centre(runs, centre));
  EXPECT_EQ(runs, 1);
  EXPECT_EQ(result.output_crossing_triangles, crossing_triangles(folded(holed, kCentre)));
  EXPECT_GT(result.output_crossing_triangles, 0u);
  EXPECT_EQ(result.vertices_guarded, 0u);
  // The same extraction, the input holed alike: guarded, and the guard mends it.
  runs = 0;
  const RemeshResult alike = finished(holed, holed, folding_centre(runs, centre));
  EXPECT_EQ(runs, 2);
  EXPECT_EQ(alike.output_crossing_triangles, 0u);
  EXPECT_GT(alike.vertices_guarded, 0u);
}

TEST(CrossingGuard, PointsNearCrossingsAreTheExtractionsVerticesWithinTheReach) {
  const TriangleMesh unfinished = grid(), finished = folded(unfinished, kCentre);
  // The corner cell's first triangle, (0, 0), (1/8, 0), (1/8, 1/8): its longest edge is √2/8
  // (0.177), its centroid (1/12, 1/24) 0.059 from (1/8, 0), 0.093 from the other two, 0.118 from
  // (0, 1/8), 0.172 from (1/4, 0) and 0.186 from (1/4, 1/8).
  const std::vector<Triangle> one{finished.triangles[0]};
  EXPECT_EQ(points_near_crossings(unfinished, finished, one, 0.6),
            (std::set<Vec3>{{0, 0, 0}, {0.125, 0, 0}, {0.125, 0.125, 0}}));
  EXPECT_EQ(
      points_near_crossings(unfinished, finished, one, 1.0),
      (std::set<Vec3>{{0, 0, 0}, {0.125, 0, 0}, {0.125, 0.125, 0}, {0, 0.125, 0}, {0.25, 0, 0}}));
}

}  // namespace
}  // namespace cvtmesh
