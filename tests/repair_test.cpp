// Shape-preserving repairs: each kind is counted, applied, and keeps the surface.
#include <gtest/gtest.h>

#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

TEST(Repair, CleanMeshIsUnchanged) {
  TriangleMesh m = icosphere(2);
  const TriangleMesh before = m;
  const RepairReport r = repair_mesh(m);
  EXPECT_FALSE(r.changed());
  EXPECT_EQ(r.summary(), "");
  EXPECT_EQ(m.vertices, before.vertices);
  EXPECT_EQ(m.triangles, before.triangles);
}

TEST(Repair, MergesExactlyDuplicateVerticesAndStitchesTheSurface) {
  // A triangle soup: each triangle with its own three corners, as STL-like writers produce.
  const TriangleMesh indexed = icosphere(2);
  TriangleMesh soup;
  for (std::size_t t = 0; t < indexed.triangles.size(); ++t) {
    const Index base = static_cast<Index>(soup.vertices.size());
    for (const Vec3& p : indexed.corners(t)) soup.vertices.push_back(p);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  const RepairReport r = repair_mesh(soup);
  EXPECT_EQ(r.duplicate_vertices_merged, 3 * indexed.triangles.size() - indexed.vertices.size());
  EXPECT_EQ(soup.vertices.size(), indexed.vertices.size());
  const TopologyReport t = analyze_topology(soup);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_NEAR(surface_area(soup), surface_area(indexed), 1e-12);
}

TEST(Repair, DropsZeroAreaTriangles) {
  TriangleMesh m = icosphere(1);
  const std::size_t n = m.triangles.size();
  // Three exactly collinear points (all coordinates exact binary fractions).
  m.vertices.push_back({0.25, 0.5, 0.75});
  m.vertices.push_back({0.5, 1.0, 1.5});
  m.vertices.push_back({1.0, 2.0, 3.0});
  const Index a = static_cast<Index>(m.vertices.size() - 3);
  m.triangles.push_back({a, a + 1, a + 2});  // collinear corners
  m.triangles.push_back({0, 0, 1});          // repeated corner
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.degenerate_triangles_removed, 2u);
  EXPECT_EQ(r.unreferenced_vertices_removed, 3u);
  EXPECT_EQ(m.triangles.size(), n);
}

TEST(Repair, KeepsNearlyDegenerateTriangles) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1e-300, 0}};
  m.triangles = {{0, 1, 2}};
  EXPECT_EQ(repair_mesh(m).degenerate_triangles_removed, 0u);
}

TEST(Repair, DropsDuplicateTrianglesInAnyOrderOrOrientation) {
  TriangleMesh m = icosphere(1);
  const std::size_t n = m.triangles.size();
  const Triangle t = m.triangles[5];
  m.triangles.push_back(t);                   // same
  m.triangles.push_back({t[1], t[2], t[0]});  // rotated
  m.triangles.push_back({t[0], t[2], t[1]});  // flipped
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.duplicate_triangles_removed, 3u);
  EXPECT_EQ(m.triangles.size(), n);
  EXPECT_EQ(m.triangles[5], t);  // the first one is kept, in place
  EXPECT_TRUE(analyze_topology(m).consistently_oriented);
}

TEST(Repair, DropsUnreferencedVerticesAndRenumbers) {
  TriangleMesh m;
  m.vertices = {{9, 9, 9}, {0, 0, 0}, {8, 8, 8}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{1, 3, 4}};
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.unreferenced_vertices_removed, 2u);
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(m.vertices[1], (Vec3{1, 0, 0}));
}

TEST(Repair, DiagnoseCountsWithoutChanging) {
  TriangleMesh m = icosphere(1);
  m.triangles.push_back(m.triangles[0]);
  const TriangleMesh before = m;
  EXPECT_EQ(diagnose_repairs(m).duplicate_triangles_removed, 1u);
  EXPECT_EQ(m.triangles, before.triangles);
  EXPECT_EQ(diagnose_repairs(m).summary(), "1 duplicate triangles removed");
}

}  // namespace
}  // namespace cvtmesh
