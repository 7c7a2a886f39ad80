// Filling an input's small holes on request (remesh --fill-holes): each hole under the length
// closes on its own vertices, oriented as the surface around it; larger holes, sheets' rims and
// loops no triangle closes stay open, each counted.
#include <gtest/gtest.h>

#include <algorithm>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// `mesh` without the triangles around vertex `v`: one hole of its valence in vertices.
TriangleMesh without_star_of(TriangleMesh mesh, Index v) {
  std::erase_if(mesh.triangles,
                [&](const Triangle& t) { return t[0] == v || t[1] == v || t[2] == v; });
  return mesh;
}

TEST(FillHoles, ClosesEachSmallHoleOnItsOwnVerticesAsTheSurfaceIsOriented) {
  TriangleMesh m = with_one_triangle_holes(icosphere(3), 20, 31);  // edges about 0.15 long
  ASSERT_EQ(analyze_topology(m).boundary_loops, 20u);
  const std::size_t vertices = m.vertices.size(), triangles = m.triangles.size();
  const HoleFilling f = fill_holes(m, 1.0);
  EXPECT_EQ(f.filled, 20u);
  EXPECT_EQ(f.triangles_added, 20u);
  EXPECT_EQ(f.left_open + f.larger, 0u);
  EXPECT_EQ(m.vertices.size(), vertices);
  EXPECT_EQ(m.triangles.size(), triangles + 20);
  const TopologyReport t = analyze_topology(m);
  EXPECT_TRUE(t.is_closed());
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(t.consistently_oriented);
  EXPECT_EQ(t.euler_characteristic, 2);
}

TEST(FillHoles, LeavesHolesAtOrOverTheLengthOpen) {
  // Five one-triangle holes (perimeter about 0.45) and the star of one of the icosahedron's
  // vertices (five edges, about 0.8 round), apart from each other.
  const TriangleMesh holed = with_one_triangle_holes(without_star_of(icosphere(3), 0), 5, 97);
  ASSERT_EQ(analyze_topology(holed).boundary_loops, 6u);
  TriangleMesh m = holed;
  HoleFilling f = fill_holes(m, 0.7);
  EXPECT_EQ(f.filled, 5u);
  EXPECT_EQ(f.larger, 1u);
  EXPECT_EQ(analyze_topology(m).boundary_loops, 1u);
  m = holed;
  f = fill_holes(m, 2.0);
  EXPECT_EQ(f.filled, 6u);
  EXPECT_EQ(f.triangles_added, 5u + 3u);  // a loop of n vertices closes with n - 2 triangles
  EXPECT_TRUE(analyze_topology(m).is_closed());
  EXPECT_TRUE(analyze_topology(m).consistently_oriented);
  m = holed;
  f = fill_holes(m, 0);
  EXPECT_EQ(f.filled, 0u);
  EXPECT_EQ(f.larger, 6u);
  EXPECT_EQ(m.triangles, holed.triangles);
  EXPECT_THROW(fill_holes(m, -1), InvalidArgument);
}

TEST(FillHoles, NeverCapsASheetsRim) {
  // A disk's and a hemisphere's rims are their whole boundary: a patch would double the sheet.
  for (const TriangleMesh& sheet : {disk(4, 12), hemisphere(6, 16)}) {
    TriangleMesh m = sheet;
    const HoleFilling f = fill_holes(m, 1e9);
    EXPECT_EQ(f.filled, 0u);
    EXPECT_EQ(f.larger, 1u);
    EXPECT_EQ(m.triangles, sheet.triangles);
  }
}

TEST(FillHoles, SaysSoWhereTheLoopsAreNotDefined) {
  // A sphere with a one-triangle hole, and a bowtie: two triangles meeting at one vertex, which
  // has two boundary edges leaving it.
  TriangleMesh m = with_one_triangle_holes(icosphere(2), 1, 7);
  const auto v = static_cast<Index>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), {{3, 0, 0}, {4, 0, 0}, {4, 1, 0}, {2, 0, 0}, {2, -1, 0}});
  m.triangles.push_back({v, v + 1, v + 2});
  m.triangles.push_back({v, v + 3, v + 4});
  const TriangleMesh before = m;
  const HoleFilling f = fill_holes(m, 1e9);
  EXPECT_TRUE(f.loops_undefined);
  EXPECT_EQ(f.filled, 0u);
  EXPECT_EQ(m.triangles, before.triangles);
  m = with_one_triangle_holes(icosphere(2), 1, 7);
  EXPECT_FALSE(fill_holes(m, 1e9).loops_undefined);
}

TEST(FillHoles, SaysSoWhereTheBoundaryMeetsEdgesOfThreeTriangles) {
  // A flap (a, v, b) over two neighbouring triangles (v, a, c) and (v, c, b) of a sphere, glued
  // along (a, v) and (v, b): its side (a, b) is the only boundary edge, and no loop closes there
  // (MeshLab's sub.obj has one; the walk stopped at a, and the one-vertex "loop" crashed CGAL's
  // hole triangulation).
  TriangleMesh m = icosphere(2);
  const Triangle first = m.triangles[0];
  const Index v = first[0], a = first[1], c = first[2];
  const auto second = std::find_if(m.triangles.begin(), m.triangles.end(), [&](const Triangle& t) {
    return std::ranges::count(t, v) && std::ranges::count(t, c) && !std::ranges::count(t, a);
  });
  ASSERT_NE(second, m.triangles.end());
  const Index b = (*second)[0] != v && (*second)[0] != c   ? (*second)[0]
                  : (*second)[1] != v && (*second)[1] != c ? (*second)[1]
                                                           : (*second)[2];
  m.triangles.push_back({a, v, b});
  const TopologyReport t = analyze_topology(m);
  ASSERT_EQ(t.nonmanifold_edges, 2u);
  ASSERT_EQ(t.boundary_edges, 1u);
  const TriangleMesh before = m;
  const HoleFilling f = fill_holes(m, 1e9);
  EXPECT_TRUE(f.loops_undefined);
  EXPECT_EQ(f.filled, 0u);
  EXPECT_EQ(m.triangles, before.triangles);
}

TEST(FillHoles, LeavesASlitNoTriangleClosesOpen) {
  // A flat square 22 wide, cut along a slit from (0, 0) to (2, 0) whose two sides share their
  // ends: the loop a0 a1 a2 a3 has no area, and every triangle on it would be degenerate.
  TriangleMesh m;
  m.vertices = {{0, 0, 0},     {1, 0, 0},   {2, 0, 0},   {1, 0, 0},  // a0 a1 a2 a3
                {-10, 10, 0},  {1, 10, 0},  {12, 10, 0},             // p0 p1 p2
                {-10, -10, 0}, {1, -10, 0}, {12, -10, 0}};           // q0 q1 q2
  m.triangles = {{0, 1, 5}, {0, 5, 4}, {1, 2, 5}, {2, 6, 5}, {0, 8, 3},
                 {0, 7, 8}, {3, 8, 2}, {2, 8, 9}, {0, 4, 7}, {2, 9, 6}};
  ASSERT_EQ(analyze_topology(m).boundary_loops, 2u);
  const TriangleMesh before = m;
  const HoleFilling f = fill_holes(m, 1e9);
  EXPECT_EQ(f.filled, 0u);
  EXPECT_EQ(f.left_open, 1u);  // the slit
  EXPECT_EQ(f.larger, 1u);     // the square's rim
  EXPECT_EQ(m.triangles, before.triangles);
}

}  // namespace
}  // namespace cvtmesh
