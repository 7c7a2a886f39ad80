// Flat pairs at the boundary: merged into the triangle without their vertex, with the boundary
// loop, the manifold and the Euler characteristic kept, and feature curves carried along the
// chord; corners, wide angles, a chord that is an edge already and curves that end there stay.
#include <gtest/gtest.h>

#include <algorithm>

#include "cvtmesh/quality.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"
#include "features/edge_uses.hpp"
#include "finish/flat_pairs.hpp"
#include "finish/worst_shape.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

// A flat disk whose first boundary edge b-c, in triangle (b, c, x), is split by a vertex v just
// outside its middle: (b, v, x) and (v, c, x), a flat pair whose angle at v is 180° − 2·atan(2 ×
// lift).
struct DiskWithPair {
  TriangleMesh mesh;
  Index b = 0, c = 0, x = 0, v = 0;
};

DiskWithPair disk_with_pair(double lift) {
  DiskWithPair d{testing::disk(4, 12)};
  const std::vector<Edge> edges = sorted_edges(d.mesh);
  for (Triangle& t : d.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      d.b = t[k], d.c = t[(k + 1) % 3], d.x = t[(k + 2) % 3];
      int uses = 0;
      for (const Triangle& u : d.mesh.triangles)
        for (int m = 0; m < 3; ++m) uses += edge_of(u[m], u[(m + 1) % 3]) == edge_of(d.b, d.c);
      if (uses != 1) continue;
      const Vec3 &p = d.mesh.vertices[d.b], &q = d.mesh.vertices[d.c];
      const Vec3 middle = 0.5 * (p + q);
      d.v = static_cast<Index>(d.mesh.vertices.size());
      d.mesh.vertices.push_back(middle + lift * norm(q - p) * ((1 / norm(middle)) * middle));
      t = {d.b, d.v, d.x};
      d.mesh.triangles.push_back({d.v, d.c, d.x});
      return d;
    }
  ADD_FAILURE() << "the disk has no boundary edge";
  return d;
}

std::vector<bool> none(const TriangleMesh& mesh) {
  return std::vector<bool>(mesh.vertices.size(), false);
}

bool has_triangle(const TriangleMesh& mesh, Triangle t) {
  for (int k = 0; k < 3; ++k) {
    if (std::find(mesh.triangles.begin(), mesh.triangles.end(), t) != mesh.triangles.end())
      return true;
    std::rotate(t.begin(), t.begin() + 1, t.end());
  }
  return false;
}

TEST(FlatPairs, AFlatPairBecomesOneTriangleAndTheBoundaryLoopStays) {
  DiskWithPair d = disk_with_pair(0.02);  // 177.7° at v
  const TriangleMesh disk = testing::disk(4, 12);
  std::vector<Edge> features;
  EXPECT_EQ(merge_flat_pairs(d.mesh, features, none(d.mesh)), 1u);
  EXPECT_EQ(d.mesh.triangles.size(), disk.triangles.size());
  EXPECT_TRUE(has_triangle(d.mesh, {d.b, d.c, d.x}));  // as the pair faced
  EXPECT_FALSE(has_triangle(d.mesh, {d.c, d.b, d.x}));
  repair_mesh(d.mesh);  // drops v
  const TopologyReport after = analyze_topology(d.mesh);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_TRUE(same_topology(after, analyze_topology(disk)));
  EXPECT_EQ(after.boundary_loops, 1u);
  EXPECT_EQ(d.mesh.vertices.size(), disk.vertices.size());
}

TEST(FlatPairs, ACornerAWideAngleAndAnExistingChordStay) {
  DiskWithPair at_corner = disk_with_pair(0.02);
  std::vector<bool> kept = none(at_corner.mesh);
  kept[at_corner.v] = true;
  std::vector<Edge> features;
  EXPECT_EQ(merge_flat_pairs(at_corner.mesh, features, kept), 0u);

  DiskWithPair wide = disk_with_pair(0.3);  // 118° at v
  EXPECT_EQ(merge_flat_pairs(wide.mesh, features, none(wide.mesh)), 0u);

  // A triangle on b-c outside: the merged triangle would use that edge a second time.
  DiskWithPair closed = disk_with_pair(0.02);
  closed.mesh.vertices.push_back(2 * closed.mesh.vertices[closed.v]);
  closed.mesh.triangles.push_back(
      {closed.c, closed.b, static_cast<Index>(closed.mesh.vertices.size() - 1)});
  EXPECT_EQ(merge_flat_pairs(closed.mesh, features, none(closed.mesh)), 0u);
}

// Two triangles over the bar on a boundary of 174°: merging would only move the boundary.
TEST(FlatPairs, APairOverTheBarStays) {
  TriangleMesh pair;
  pair.vertices = {{0, 0, 0}, {1, -0.05, 0}, {2, 0, 0}, {1, 1, 0}};  // a, v, b, c
  pair.triangles = {{0, 1, 3}, {1, 2, 3}};
  for (const Triangle& t : pair.triangles) {
    const MinShape s = min_shape(pair.vertices[t[0]], pair.vertices[t[1]], pair.vertices[t[2]]);
    ASSERT_GE(s.quality, kBarQuality);
    ASSERT_GE(s.min_angle, kBarAngleDeg);
  }
  std::vector<Edge> features;
  EXPECT_EQ(merge_flat_pairs(pair, features, none(pair)), 0u);
  pair.vertices[3] = {1, 3, 0};  // now both under the bar (18°), the merged one better (37°)
  EXPECT_EQ(merge_flat_pairs(pair, features, none(pair)), 1u);
}

TEST(FlatPairs, AFeatureCurveAlongTheBoundaryRunsAlongTheChord) {
  DiskWithPair d = disk_with_pair(0.02);
  std::vector<Edge> features{edge_of(d.b, d.v), edge_of(d.v, d.c)};
  std::sort(features.begin(), features.end());
  EXPECT_EQ(merge_flat_pairs(d.mesh, features, none(d.mesh)), 1u);
  EXPECT_EQ(features, std::vector<Edge>{edge_of(d.b, d.c)});
}

TEST(FlatPairs, AFeatureCurveThatEndsAtTheVertexKeepsIt) {
  for (const bool crease : {false, true}) {
    DiskWithPair d = disk_with_pair(0.02);
    std::vector<Edge> features{crease ? edge_of(d.v, d.x) : edge_of(d.b, d.v)};
    EXPECT_EQ(merge_flat_pairs(d.mesh, features, none(d.mesh)), 0u) << "crease " << crease;
    EXPECT_EQ(features.size(), 1u);
  }
}

}  // namespace
}  // namespace cvtmesh
