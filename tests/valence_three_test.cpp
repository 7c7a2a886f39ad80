// Vertices of three triangles (remesh/valence_three): removed for the triangle they split, with
// the topology kept, only where that triangle is better, near, and new.
#include <gtest/gtest.h>

#include "cvtmesh/quality.hpp"
#include "cvtmesh/topology.hpp"
#include "remesh/valence_three.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

// A flat disk with triangle t split in three at a point `lift` above its centroid.
TriangleMesh disk_with_split(double lift, std::size_t t = 7) {
  TriangleMesh m = testing::disk(4, 12);
  const Triangle f = m.triangles[t];
  const auto [a, b, c] = m.corners(t);
  const auto v = static_cast<Index>(m.vertices.size());
  m.vertices.push_back((1.0 / 3) * (a + b + c) + Vec3{0, 0, lift * distance(a, b)});
  m.triangles[t] = {f[0], f[1], v};
  m.triangles.push_back({f[1], f[2], v});
  m.triangles.push_back({f[2], f[0], v});
  return m;
}

TEST(ValenceThree, ASplitTriangleIsMergedBackWithTheTopologyKept) {
  TriangleMesh m = disk_with_split(0.05);
  const TopologyReport before = analyze_topology(m);
  const double qmin = measure_quality(m).q_min;
  EXPECT_EQ(remove_valence_three(m, std::vector<bool>(m.vertices.size(), true)), 1u);
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
  EXPECT_EQ(remove_valence_three(m, removable), 0u);
  TriangleMesh peak = disk_with_split(0.5);  // a spike the surface has: not flattened
  EXPECT_EQ(remove_valence_three(peak, std::vector<bool>(peak.vertices.size(), true)), 0u);
  // A tetrahedron: each vertex has three triangles, and the one it would leave is there already.
  TriangleMesh tetra;
  tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  EXPECT_EQ(remove_valence_three(tetra, std::vector<bool>(4, true)), 0u);
  EXPECT_EQ(tetra.triangles.size(), 4u);
}

}  // namespace
}  // namespace cvtmesh
