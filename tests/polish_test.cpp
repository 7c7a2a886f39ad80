// Local Lloyd polishing of the output: finds badly shaped triangles, removes them by moving only
// the seeds around them, and is off when asked.
#include <gtest/gtest.h>

#include <algorithm>

#include "cvt/polish_defects.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/sampling.hpp"
#include "geometry/surface_projector.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// A converged remesh (features off) with one seed moved 80% of the way to a neighbour: the short
// edge between them makes slivers that the optimization (0 iterations here) leaves alone.
struct Defect {
  TriangleMesh surface;
  std::vector<Vec3> seeds;
  Vec3 at;
};

// Vertices stay on the surface (no fit), so that an output's vertices are seeds on it.
RemeshSettings featureless() {
  RemeshSettings s;
  s.features.sharp_edges = false;
  s.fit_rounds = 0;
  return s;
}

// `seeds` on `surface` with the first seed of triangle t dragged towards its second.
Defect dragged(const TriangleMesh& surface, std::vector<Vec3> seeds, const Triangle& t) {
  Defect d{surface, std::move(seeds), {}};
  d.seeds[t[0]] = d.seeds[t[0]] + 0.8 * (d.seeds[t[1]] - d.seeds[t[0]]);
  d.at = d.seeds[t[0]];
  return d;
}

Defect make_defect() {
  const TriangleMesh sphere = icosphere(4);
  RemeshSettings s = featureless();
  s.vertices = 800;
  const TriangleMesh converged = remesh(sphere, s).mesh;
  return dragged(sphere, converged.vertices, converged.triangles.front());
}

RemeshResult remesh_from(const Defect& d, int polish_rounds) {
  RemeshSettings s = featureless();
  s.initial_seeds = d.seeds;
  s.mode = CvtMode::ccvt;
  s.iterations = 0;
  s.polish_rounds = polish_rounds;
  s.shape_sweeps = 0;  // polishing alone (improve_shapes_test tests the last step)
  return remesh(d.surface, s);
}

// The seeds of `after` that are not where they were in `before`.
std::vector<Vec3> moved_seeds(const std::vector<Vec3>& before, const TriangleMesh& after) {
  std::vector<Vec3> moved;
  for (const Vec3& v : after.vertices) {
    const auto nearest = std::min_element(
        before.begin(), before.end(), [&](auto& a, auto& b) { return norm(a - v) < norm(b - v); });
    if (norm(*nearest - v) > 1e-9) moved.push_back(v);
  }
  return moved;
}

TEST(Polish, WithoutPolishingTheDefectStays) {
  const Defect d = make_defect();
  const RemeshResult r = remesh_from(d, 0);
  EXPECT_LT(measure_quality(r.mesh).angle_min_deg, 30.0);
  EXPECT_EQ(r.polish_rounds, 0);
}

TEST(Polish, RemovesTheDefectMovingOnlySeedsNearIt) {
  const Defect d = make_defect();
  const RemeshResult r = remesh_from(d, 3);
  EXPECT_GT(r.defects_polished, 0u);
  EXPECT_GE(r.polish_rounds, 1);
  const QualityReport q = measure_quality(r.mesh);
  EXPECT_GE(q.angle_min_deg, 30.0);
  EXPECT_GE(q.q_min, 0.6);
  // Seeds far from the defect kept their place (up to the projection's rounding); the moved
  // ones are all near it. 800 seeds on the unit sphere are about 0.13 apart.
  const std::vector<Vec3> moved = moved_seeds(d.seeds, r.mesh);
  for (const Vec3& v : moved) EXPECT_LT(norm(v - d.at), 0.8) << "a seed far from the defect moved";
  EXPECT_GT(moved.size(), 2u);
  EXPECT_LT(moved.size(), d.seeds.size() / 10);
}

// A thin slab (2 × 2 × 0.2, each face two triangles) with 1000 seeds about 0.1 apart: the
// triangles are far larger than the cells, and the two big faces are two cells apart. Moving
// cells must not take in the parts of those triangles that far-away cells own (under a defect
// near the rim, the opposite face): that pulled seeds across the slab, a dozen cells away, and
// left slivers (2.5° for one of these defects).
TEST(Polish, OnFacetsLargerThanTheCellsRemovesTheDefect) {
  TriangleMesh slab = cube(1);
  for (Vec3& v : slab.vertices) v.z *= 0.1;
  RemeshSettings s = featureless();
  s.vertices = 1000;
  const TriangleMesh converged = remesh(slab, s).mesh;
  for (std::size_t k = 0; k < converged.triangles.size(); k += converged.triangles.size() / 8) {
    const RemeshResult r =
        remesh_from(dragged(slab, converged.vertices, converged.triangles[k]), 3);
    const QualityReport q = measure_quality(r.mesh);
    EXPECT_GE(q.angle_min_deg, 30.0) << "defect at triangle " << k;
    EXPECT_GE(q.q_min, 0.6) << "defect at triangle " << k;
  }
}

// Topology control polishes after each of its rounds, which change a few seeds: a defect that the
// polishing before left as it was, its seeds where they were, is not polished again; one whose
// seed moved since is, and only the seeds around it move.
TEST(Polish, PolishesAgainOnlyTheDefectsWhoseSeedsChanged) {
  const TriangleMesh sphere = icosphere(4);
  const SurfaceProjector projector(sphere);
  const CvtObjective placement(sphere, &projector);
  // Random seeds, one round of one step: most defects stay.
  std::vector<Vec3> seeds = sample_surface(sphere, 800, 1);
  const PolishSettings one_step{1, 1};
  ExtractionMemory memory(sphere, placement.interrupt());
  ASSERT_EQ(extract_polished(sphere, seeds, placement, one_step, memory).rounds, 1);
  const std::vector<Vec3> polished = seeds;

  const PolishedOutput again =
      extract_polished(sphere, seeds, placement, one_step, memory, &polished);
  ASSERT_GT(again.defects, 0u);
  EXPECT_EQ(again.rounds, 0);
  EXPECT_TRUE(seeds == polished) << "a seed moved";
  // Not told what was polished, it polishes them all again, far and wide.
  std::vector<Vec3> unrecorded = polished;
  EXPECT_EQ(extract_polished(sphere, unrecorded, placement, one_step, memory).rounds, 1);
  std::size_t moved_unrecorded = 0;
  for (std::size_t s = 0; s < seeds.size(); ++s) moved_unrecorded += unrecorded[s] != polished[s];

  // A seed of a defect moves a little: that defect is polished, near it only. 800 seeds on the
  // unit sphere are about 0.13 apart.
  const Triangle defect = *std::find_if(
      again.mesh.triangles.begin(), again.mesh.triangles.end(), [&](const Triangle& t) {
        const TriangleShape shape = triangle_shape(
            again.mesh.vertices[t[0]], again.mesh.vertices[t[1]], again.mesh.vertices[t[2]]);
        return shape.min_angle < 35 || shape.quality < 0.65;
      });
  const Index k = defect[0];
  seeds[k] = placement.constrained(k, seeds[k] + 0.1 * (seeds[defect[1]] - seeds[k]));
  const std::vector<Vec3> nudged = seeds;
  EXPECT_EQ(extract_polished(sphere, seeds, placement, one_step, memory, &polished).rounds, 1);
  std::size_t moved = 0;
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    if (seeds[s] == nudged[s]) continue;
    ++moved;
    EXPECT_LT(norm(seeds[s] - nudged[k]), 0.5) << "seed " << s << " far from the nudged one moved";
  }
  EXPECT_GT(moved, 0u);
  EXPECT_LT(4 * moved, moved_unrecorded);
}

// Told to polish around some seeds (topology control's first polish of an adaptive output, around
// where it fails), it polishes the defects near them only: of two defects on opposite sides of a
// sphere, the one far from them stays.
TEST(Polish, AroundGivenSeedsPolishesOnlyTheDefectsNearThem) {
  const TriangleMesh sphere = icosphere(4);
  const SurfaceProjector projector(sphere);
  const CvtObjective placement(sphere, &projector);
  RemeshSettings s = featureless();
  s.vertices = 800;
  const TriangleMesh converged = remesh(sphere, s).mesh;
  // A defect at the first triangle, and one at the triangle whose centroid is farthest from it.
  const auto centroid = [&](const Triangle& t) {
    return (1.0 / 3) *
           (converged.vertices[t[0]] + converged.vertices[t[1]] + converged.vertices[t[2]]);
  };
  const Triangle near = converged.triangles.front();
  const Triangle far = *std::max_element(
      converged.triangles.begin(), converged.triangles.end(), [&](auto& a, auto& b) {
        return norm(centroid(a) - centroid(near)) < norm(centroid(b) - centroid(near));
      });
  const Defect first = dragged(sphere, converged.vertices, near);
  const Defect both = dragged(sphere, first.seeds, far);
  const auto moved_near = [&](const std::vector<Vec3>& seeds, const Vec3& at) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < seeds.size(); ++k)
      n += seeds[k] != both.seeds[k] && norm(both.seeds[k] - at) < 0.5;
    return n;
  };

  ExtractionMemory memory(sphere, placement.interrupt());
  std::vector<Vec3> everywhere = both.seeds;
  ASSERT_EQ(extract_polished(sphere, everywhere, placement, {1, 10}, memory).rounds, 1);
  ASSERT_GT(moved_near(everywhere, first.at), 0u);
  ASSERT_GT(moved_near(everywhere, both.at), 0u);

  PolishSettings around{1, 10};
  around.around = {near[0]};
  std::vector<Vec3> seeds = both.seeds;
  EXPECT_EQ(extract_polished(sphere, seeds, placement, around, memory).rounds, 1);
  EXPECT_GT(moved_near(seeds, first.at), 0u);
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    if (seeds[k] == both.seeds[k]) continue;
    EXPECT_LT(norm(both.seeds[k] - first.at), 1.0) << "seed " << k << " far from them moved";
  }
}

}  // namespace
}  // namespace cvtmesh
