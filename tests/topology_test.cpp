// Counts, boundaries, manifoldness and genus on meshes generated in code.
#include <gtest/gtest.h>

#include "cvtmesh/topology.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

TEST(Topology, IcosphereIsAClosedGenusZeroSurface) {
  const TopologyReport t = analyze_topology(icosphere(3));
  EXPECT_EQ(t.vertices, 642u);
  EXPECT_EQ(t.triangles, 1280u);
  EXPECT_EQ(t.edges, 1920u);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.boundary_loops, 0u);
  EXPECT_EQ(t.nonmanifold_edges, 0u);
  EXPECT_EQ(t.euler_characteristic, 2);
  ASSERT_TRUE(t.genus.has_value());
  EXPECT_EQ(*t.genus, 0);
  EXPECT_TRUE(t.consistently_oriented);
}

TEST(Topology, TorusHasGenusOne) {
  const TopologyReport t = analyze_topology(torus(2, 0.5, 24, 12));
  EXPECT_EQ(t.vertices, 288u);
  EXPECT_EQ(t.triangles, 576u);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.boundary_loops, 0u);
  ASSERT_TRUE(t.genus.has_value());
  EXPECT_EQ(*t.genus, 1);
  EXPECT_TRUE(t.consistently_oriented);
}

TEST(Topology, SubdividedCubeIsClosedAndConsistentlyOriented) {
  const int n = 4;
  const TopologyReport t = analyze_topology(cube(n));
  EXPECT_EQ(t.vertices, static_cast<std::size_t>(6 * (n - 1) * (n - 1) + 12 * (n - 1) + 8));
  EXPECT_EQ(t.triangles, static_cast<std::size_t>(12 * n * n));
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.boundary_edges, 0u);
  EXPECT_EQ(*t.genus, 0);
  EXPECT_TRUE(t.consistently_oriented);
}

TEST(Topology, OpenDiskHasOneBoundaryLoop) {
  const TopologyReport t = analyze_topology(disk(5, 16));
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.boundary_edges, 16u);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(*t.genus, 0);
  EXPECT_FALSE(t.is_closed());
}

TEST(Topology, TwoDisjointSpheresAreTwoComponents) {
  const TriangleMesh s = icosphere(2);
  const TopologyReport t = analyze_topology(concatenate(s, transformed(s, 1.0, {5, 0, 0})));
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.euler_characteristic, 4);
  EXPECT_EQ(*t.genus, 0);
}

TEST(Topology, SphereWithTwoHolesHasTwoLoops) {
  TriangleMesh m = icosphere(2);
  // Remove triangle 0 and the triangle on the far side of the sphere from it.
  auto centroid = [&](std::size_t t) {
    const auto [a, b, c] = m.corners(t);
    return (1.0 / 3) * (a + b + c);
  };
  std::size_t far = 0;
  for (std::size_t t = 1; t < m.triangles.size(); ++t)
    if (distance(centroid(t), centroid(0)) > distance(centroid(far), centroid(0))) far = t;
  m.triangles.erase(m.triangles.begin() + far);
  m.triangles.erase(m.triangles.begin());
  const TopologyReport t = analyze_topology(m);
  EXPECT_EQ(t.boundary_loops, 2u);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(*t.genus, 0);
}

TEST(Topology, ThreeTrianglesOnOneEdgeAreNonManifold) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const TopologyReport t = analyze_topology(m);
  EXPECT_EQ(t.nonmanifold_edges, 1u);
  EXPECT_FALSE(t.genus.has_value());
}

TEST(Topology, TwoTetrahedraSharingAVertexMakeANonManifoldVertex) {
  TriangleMesh tet;
  tet.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  TriangleMesh m = concatenate(tet, transformed(tet, -1.0));
  for (Triangle& f : m.triangles)
    for (Index& v : f)
      if (v == 4) v = 0;  // the second tetrahedron's apex is the first one's
  const TopologyReport t = analyze_topology(m);
  EXPECT_EQ(t.nonmanifold_vertices, 1u);
  EXPECT_EQ(t.nonmanifold_edges, 0u);
  EXPECT_EQ(t.components, 1u);
  EXPECT_FALSE(t.genus.has_value());
}

TEST(Topology, FlippedTriangleIsOrientableButNotConsistent) {
  TriangleMesh m = icosphere(1);
  std::swap(m.triangles[3][0], m.triangles[3][1]);
  const TopologyReport t = analyze_topology(m);
  EXPECT_TRUE(t.orientable);
  EXPECT_FALSE(t.consistently_oriented);
}

TEST(Topology, MoebiusStripIsNotOrientable) {
  const TriangleMesh m = moebius_strip(12);
  const TopologyReport t = analyze_topology(m);
  EXPECT_FALSE(t.orientable);
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_FALSE(t.genus.has_value());
}

TEST(Topology, UnreferencedVerticesAreNotCounted) {
  TriangleMesh m = icosphere(1);
  m.vertices.push_back({9, 9, 9});
  const TopologyReport t = analyze_topology(m);
  EXPECT_EQ(t.unreferenced_vertices, 1u);
  EXPECT_EQ(t.euler_characteristic, 2);
}

TEST(Topology, SameTopologyComparesComponentsEulerAndLoops) {
  const TopologyReport sphere = analyze_topology(icosphere(2));
  EXPECT_TRUE(same_topology(sphere, analyze_topology(icosphere(3))));
  EXPECT_FALSE(same_topology(sphere, analyze_topology(torus(2, 0.5, 16, 8))));
  EXPECT_FALSE(same_topology(sphere, analyze_topology(disk(3, 8))));
}

}  // namespace
}  // namespace cvtmesh
