// Flat and folded ears at the boundary: removed, with the boundary loop, the manifold and the
// Euler characteristic kept; corners, ears that are neither and lone triangles stay.
#include <gtest/gtest.h>

#include <cmath>

#include "cvtmesh/quality.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"
#include "finish/flat_ears.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

// A flat disk with one more vertex just outside the middle of a boundary edge b-c, and the
// triangle (c, b, ear) on that edge: an ear whose angle at the new vertex is 180° − 2·atan(lift /
// half the edge).
TriangleMesh disk_with_ear(double lift) {
  TriangleMesh mesh = testing::disk(4, 12);
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index b = t[k], c = t[(k + 1) % 3];
      int uses = 0;
      for (const Triangle& u : mesh.triangles)
        for (int m = 0; m < 3; ++m)
          uses += (u[m] == b && u[(m + 1) % 3] == c) || (u[m] == c && u[(m + 1) % 3] == b);
      if (uses != 1) continue;
      const Vec3 middle = 0.5 * (mesh.vertices[b] + mesh.vertices[c]);
      const Vec3 outward = (1 / norm(middle)) * middle;
      mesh.vertices.push_back(middle + lift * norm(mesh.vertices[c] - mesh.vertices[b]) * outward);
      mesh.triangles.push_back({c, b, static_cast<Index>(mesh.vertices.size() - 1)});
      return mesh;
    }
  ADD_FAILURE() << "the disk has no boundary edge";
  return mesh;
}

// No vertex seedless: every one a seed.
std::vector<bool> none(const TriangleMesh& mesh) {
  return std::vector<bool>(mesh.vertices.size(), false);
}

TEST(FlatEars, AFlatEarGoesAndTheBoundaryLoopStays) {
  TriangleMesh mesh = disk_with_ear(0.02);  // 175.4° at the ear's vertex
  const TopologyReport before = analyze_topology(testing::disk(4, 12));
  EXPECT_LT(measure_quality(mesh).angle_min_deg, 3);
  EXPECT_EQ(remove_flat_ears(mesh, none(mesh), none(mesh)), 1u);
  repair_mesh(mesh);
  const TopologyReport after = analyze_topology(mesh);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_TRUE(same_topology(after, before));
  EXPECT_EQ(after.boundary_loops, 1u);
  EXPECT_EQ(mesh.triangles.size(), testing::disk(4, 12).triangles.size());
  EXPECT_GT(measure_quality(mesh).angle_min_deg, 10);
}

// A corner's ear whose vertex lies on top of a neighbour (as two corners 6e-34 apart at a
// non-manifold vertex of octagonal_pocket.stl did): no area, so it goes; the neighbour stays.
TEST(FlatEars, AnEarOnTopOfItsNeighbourGoesEvenAtACorner) {
  TriangleMesh mesh = disk_with_ear(0.02);
  const Triangle ear = mesh.triangles.back();
  const Vec3 neighbour = mesh.vertices[ear[0]];
  mesh.vertices.back() = neighbour + Vec3{1e-30, 0, 0};
  std::vector<bool> kept(mesh.vertices.size(), false);
  kept.back() = true;
  EXPECT_EQ(measure_quality(mesh).angle_min_deg, 0);
  EXPECT_EQ(remove_flat_ears(mesh, kept, none(mesh)), 1u);
  EXPECT_EQ(mesh.vertices[ear[0]], neighbour);
  repair_mesh(mesh);
  EXPECT_TRUE(same_topology(analyze_topology(mesh), analyze_topology(testing::disk(4, 12))));
  EXPECT_GT(measure_quality(mesh).angle_min_deg, 10);
}

TEST(FlatEars, CornersEarsThatAreNotFlatAndLoneTrianglesStay) {
  TriangleMesh at_corner = disk_with_ear(0.02);
  std::vector<bool> kept(at_corner.vertices.size(), false);
  kept.back() = true;
  EXPECT_EQ(remove_flat_ears(at_corner, kept, none(at_corner)), 0u);
  EXPECT_EQ(at_corner.triangles.size(), disk_with_ear(0.02).triangles.size());

  TriangleMesh pointed = disk_with_ear(0.2);  // 136° at the ear's vertex
  EXPECT_EQ(remove_flat_ears(pointed, none(pointed), none(pointed)), 0u);

  // Every corner of a lone sliver has two boundary edges: it is a component, not an ear.
  TriangleMesh sliver{{{0, 0, 0}, {1, 0, 0}, {0.5, 0.01, 0}}, {{0, 1, 2}}};
  EXPECT_EQ(remove_flat_ears(sliver, none(sliver), none(sliver)), 0u);
  EXPECT_EQ(sliver.triangles.size(), 1u);
}

// An ear at 136° stays where its vertex is a seed, and goes where it is none (a cell's far
// piece): from 120° on, unless it is a corner.
TEST(FlatEars, ASeedlessEarGoesFrom120Degrees) {
  TriangleMesh mesh = disk_with_ear(0.2);
  std::vector<bool> seedless = none(mesh);
  seedless.back() = true;
  std::vector<bool> kept = none(mesh);
  kept.back() = true;
  EXPECT_EQ(remove_flat_ears(mesh, none(mesh), none(mesh)), 0u);
  EXPECT_EQ(remove_flat_ears(mesh, kept, seedless), 0u);
  EXPECT_EQ(remove_flat_ears(mesh, none(mesh), seedless), 1u);
  repair_mesh(mesh);
  EXPECT_TRUE(same_topology(analyze_topology(mesh), analyze_topology(testing::disk(4, 12))));
  TriangleMesh pointed = disk_with_ear(0.4);  // 102° at the ear's vertex
  std::vector<bool> pointed_seedless = none(pointed);
  pointed_seedless.back() = true;
  EXPECT_EQ(remove_flat_ears(pointed, none(pointed), pointed_seedless), 0u);
}

// An ear whose vertex lies inside the disk, across the chord: a triangle folded back over its
// neighbour (136° at its vertex, so not flat). It goes, unless its vertex is a corner.
TEST(FlatEars, AnEarFoldedBackOverItsNeighbourGoes) {
  TriangleMesh mesh = disk_with_ear(-0.2);
  std::vector<bool> kept(mesh.vertices.size(), false);
  kept.back() = true;
  EXPECT_EQ(remove_flat_ears(mesh, kept, none(mesh)), 0u);
  EXPECT_EQ(remove_flat_ears(mesh, none(mesh), none(mesh)), 1u);
  repair_mesh(mesh);
  const TopologyReport after = analyze_topology(mesh);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_TRUE(same_topology(after, analyze_topology(testing::disk(4, 12))));
  EXPECT_EQ(mesh.triangles.size(), testing::disk(4, 12).triangles.size());
}

// An ear whose vertex also has another fan (a pinch) is not removed: that would change the
// boundary where the fans meet.
TEST(FlatEars, APinchedVertexKeepsItsEar) {
  TriangleMesh mesh = disk_with_ear(0.02);
  const Index ear = static_cast<Index>(mesh.vertices.size() - 1);
  const Vec3 p = mesh.vertices[ear];
  mesh.vertices.push_back(p + Vec3{0, 0, 1});
  mesh.vertices.push_back(p + Vec3{0.1, 0, 1});
  const auto n = static_cast<Index>(mesh.vertices.size());
  mesh.triangles.push_back({ear, n - 2, n - 1});
  EXPECT_EQ(remove_flat_ears(mesh, none(mesh), none(mesh)), 0u);
}

}  // namespace
}  // namespace cvtmesh
