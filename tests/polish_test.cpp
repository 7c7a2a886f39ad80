// Local Lloyd polishing of the output: finds badly shaped triangles, removes them by moving only
// the seeds around them, and is off when asked.
#include <gtest/gtest.h>

#include <algorithm>

#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// A converged sphere remesh whose seed `dragged` is moved 80% of the way to a neighbour: the
// short edge between them makes slivers that the optimization (0 iterations here) leaves alone.
struct Defect {
  TriangleMesh surface = icosphere(4);
  std::vector<Vec3> seeds;
  Vec3 at;
};

Defect make_defect() {
  Defect d;
  RemeshSettings s;
  s.vertices = 800;
  const TriangleMesh converged = remesh(d.surface, s).mesh;
  d.seeds = converged.vertices;
  const Triangle& t = converged.triangles.front();
  d.seeds[t[0]] = d.seeds[t[0]] + 0.8 * (d.seeds[t[1]] - d.seeds[t[0]]);
  d.at = d.seeds[t[0]];
  return d;
}

RemeshResult remesh_from(const Defect& d, int polish_rounds) {
  RemeshSettings s;
  s.initial_seeds = d.seeds;
  s.mode = CvtMode::ccvt;
  s.iterations = 0;
  s.polish_rounds = polish_rounds;
  return remesh(d.surface, s);
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
  std::size_t moved = 0;
  for (const Vec3& v : r.mesh.vertices) {
    const auto nearest = std::min_element(d.seeds.begin(), d.seeds.end(), [&](auto& a, auto& b) {
      return norm(a - v) < norm(b - v);
    });
    if (norm(*nearest - v) < 1e-9) continue;
    ++moved;
    EXPECT_LT(norm(v - d.at), 0.8) << "a seed far from the defect moved";
  }
  EXPECT_GT(moved, 2u);
  EXPECT_LT(moved, d.seeds.size() / 10);
}

}  // namespace
}  // namespace cvtmesh
