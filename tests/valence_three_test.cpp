// Vertices of three triangles (finish/valence_three): removed for the triangle they split, with
// the topology kept, only where that triangle is better, near, and new.
#include <gtest/gtest.h>

#include <optional>

#include "cvtmesh/quality.hpp"
#include "cvtmesh/topology.hpp"
#include "finish/valence_three.hpp"
#include "geometry/surface_projector.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

// A flat disk with triangle t split in three at a point `lift` above `at` (its centroid when not
// given), both in units of the triangle's first edge.
TriangleMesh disk_with_split(double lift, std::size_t t = 7, std::optional<Vec3> at = {}) {
  TriangleMesh m = testing::disk(4, 12);
  const Triangle f = m.triangles[t];
  const auto [a, b, c] = m.corners(t);
  const auto v = static_cast<Index>(m.vertices.size());
  m.vertices.push_back(at.value_or((1.0 / 3) * (a + b + c)) + Vec3{0, 0, lift * distance(a, b)});
  m.triangles[t] = {f[0], f[1], v};
  m.triangles.push_back({f[1], f[2], v});
  m.triangles.push_back({f[2], f[0], v});
  return m;
}

TEST(ValenceThree, ASplitTriangleIsMergedBackWithTheTopologyKept) {
  TriangleMesh m = disk_with_split(0.05);
  const TopologyReport before = analyze_topology(m);
  const double qmin = measure_quality(m).q_min;
  const SurfaceProjector disk(testing::disk(4, 12));
  EXPECT_EQ(remove_valence_three(m, std::vector<bool>(m.vertices.size(), true), disk), 1u);
  const TopologyReport after = analyze_topology(m);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_TRUE(after.consistently_oriented);
  EXPECT_TRUE(same_topology(after, before));
  EXPECT_EQ(after.unreferenced_vertices, 1u);
  EXPECT_GT(measure_quality(m).q_min, qmin);
}

TEST(ValenceThree, KeptWhenNotRemovableTooFarOffItsPlaneOrTheTriangleExists) {
  TriangleMesh m = disk_with_split(0.05);
  std::vector<bool> removable(m.vertices.size(), true);
  removable.back() = false;
  const SurfaceProjector disk(testing::disk(4, 12));
  EXPECT_EQ(remove_valence_three(m, removable, disk), 0u);
  TriangleMesh peak = disk_with_split(0.5);  // a spike the surface has: not flattened
  EXPECT_EQ(remove_valence_three(peak, std::vector<bool>(peak.vertices.size(), true),
                                 SurfaceProjector(peak)),
            0u);
  // A bump the surface has, low enough to be within a fifth of the edge of the plane: the new
  // triangle would cut through it.
  TriangleMesh bump = disk_with_split(0.15);
  EXPECT_EQ(remove_valence_three(bump, std::vector<bool>(bump.vertices.size(), true),
                                 SurfaceProjector(bump)),
            0u);
  // A tetrahedron: each vertex has three triangles, and the one it would leave is there already.
  TriangleMesh tetra;
  tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  EXPECT_EQ(remove_valence_three(tetra, std::vector<bool>(4, true), SurfaceProjector(tetra)), 0u);
  EXPECT_EQ(tetra.triangles.size(), 4u);
}

// The split point close to the triangle's first edge and a little off the flat surface: the
// sliver on that edge tilts by 59° (atan(0.05 / 0.03)), but the three lie within 0.02 of the
// edge of the surface and the triangle merged back on it.
TEST(ValenceThree, ASliverTiltedOffTheSurfaceIsMergedBackToo) {
  const TriangleMesh flat = testing::disk(4, 12);
  const auto [a, b, c] = flat.corners(7);
  const Vec3 near_edge =
      0.5 * (a + b) + 0.03 * distance(a, b) * (1 / norm(c - 0.5 * (a + b))) * (c - 0.5 * (a + b));
  TriangleMesh m = disk_with_split(0.05, 7, near_edge);
  const double qmin = measure_quality(m).q_min;
  EXPECT_EQ(
      remove_valence_three(m, std::vector<bool>(m.vertices.size(), true), SurfaceProjector(flat)),
      1u);
  EXPECT_GT(measure_quality(m).q_min, qmin);
}

}  // namespace
}  // namespace cvtmesh
