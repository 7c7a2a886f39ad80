// Shape-preserving repairs: each kind is counted, applied, and keeps the surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"
#include "geometry/orient_triangles.hpp"
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

TEST(Repair, KeepsApartDuplicatesWhoseMergeWouldMakeTheMeshNonManifold) {
  // Two closed spheres touching at one point, each with its own vertex there: merging the two
  // would make a non-manifold vertex, so they stay apart (diplodocus.off's touching parts).
  const TriangleMesh a = icosphere(1);
  TriangleMesh b = transformed(icosphere(1), 1.0,
                               {2 * a.vertices[0].x, 2 * a.vertices[0].y, 2 * a.vertices[0].z});
  // b's vertex opposite to a.vertices[0] is -a.vertices[0] shifted: exactly a.vertices[0].
  TriangleMesh both = concatenate(a, b);
  const TopologyReport before = analyze_topology(both);
  const RepairReport r = repair_mesh(both);
  EXPECT_EQ(r.duplicate_vertices_merged, 0u);
  EXPECT_EQ(r.duplicate_vertices_kept_apart, 1u);
  EXPECT_NE(r.summary().find("kept apart"), std::string::npos);
  const TopologyReport after = analyze_topology(both);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
  EXPECT_EQ(after.components, 2u);
}

TEST(Repair, MergesCopiesOfAPinchThatOnlyCloseSlitsInItsFans) {
  // A hexagon around a centre stored twice (triangles 0-2 at copy 7, 3-5 at copy 8: slits along
  // two spokes), and a triangle standing on copy 7 alone: 7 is a pinch of two fans already.
  // Merging 8 into it closes the slits and leaves it two fans, no worse: merged (teapot.obj of a
  // public test set). Two copies whose merge makes the pinch stay apart (the test above).
  TriangleMesh m;
  for (int k = 0; k < 6; ++k)
    m.vertices.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0});
  m.vertices.push_back({0, 0, 0});  // 6: the third corner of the standing triangle, moved below
  m.vertices.push_back({0, 0, 0});  // 7
  m.vertices.push_back({0, 0, 0});  // 8
  m.vertices[6] = {0.2, 0, 1};
  m.vertices.push_back({-0.2, 0, 1});  // 9
  for (Index k = 0; k < 6; ++k)
    m.triangles.push_back({k < 3 ? Index{7} : Index{8}, k, (k + 1) % 6});
  m.triangles.push_back({7, 6, 9});
  // The pinch, and the two rim vertices where the slits open (two fans each).
  ASSERT_EQ(analyze_topology(m).nonmanifold_vertices, 3u);
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.duplicate_vertices_merged, 1u);
  EXPECT_EQ(r.duplicate_vertices_kept_apart, 0u);
  const TopologyReport t = analyze_topology(m);
  EXPECT_EQ(t.nonmanifold_vertices, 1u);  // the pinch, as it was; the slits are closed
  EXPECT_EQ(t.nonmanifold_edges, 0u);
  EXPECT_EQ(t.boundary_loops, 2u);  // the hexagon's rim and the standing triangle: no slit
  EXPECT_EQ(m.vertices.size(), 9u);
}

TEST(Repair, StitchesASeamButNotAWeldAlongAnEdge) {
  // A cube cut open along one edge (its vertices duplicated on one side) stitches back; a second
  // cube glued face to face along an edge (sharing two duplicated vertices) would put four
  // triangles on that edge, and stays apart.
  TriangleMesh seam = cube(1);
  std::size_t seam_dups = 0;
  for (Triangle& t : seam.triangles) {
    const Vec3 c = (1.0 / 3) * (seam.vertices[t[0]] + seam.vertices[t[1]] + seam.vertices[t[2]]);
    if (c.x < 0.99) continue;  // the +x face gets its own copies of its corners
    for (Index& v : t) {
      seam.vertices.push_back(seam.vertices[v]);
      v = static_cast<Index>(seam.vertices.size() - 1);
      ++seam_dups;
    }
  }
  const RepairReport stitched = repair_mesh(seam);
  EXPECT_EQ(stitched.duplicate_vertices_kept_apart, 0u);
  EXPECT_EQ(stitched.duplicate_vertices_merged, seam_dups);
  EXPECT_TRUE(analyze_topology(seam).is_manifold());
  EXPECT_EQ(analyze_topology(seam).euler_characteristic, 2);

  const TriangleMesh one = cube(1);
  TriangleMesh weld = concatenate(one, transformed(one, 1.0, {2, 2, 0}));  // share the edge x=y=1
  const RepairReport kept = repair_mesh(weld);
  EXPECT_EQ(kept.duplicate_vertices_merged, 0u);
  EXPECT_EQ(kept.duplicate_vertices_kept_apart, 2u);
  EXPECT_TRUE(analyze_topology(weld).is_manifold());
}

// `mesh` as a triangle soup: each triangle with its own three corners, as STL-like writers
// produce.
TriangleMesh soup_of(const TriangleMesh& mesh) {
  TriangleMesh soup;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Index base = static_cast<Index>(soup.vertices.size());
    for (const Vec3& p : mesh.corners(t)) soup.vertices.push_back(p);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  return soup;
}

TEST(Repair, StitchesASoupOfPartsThatTouchAndKeepsThemApartOnlyWhereTheyTouch) {
  // Two spheres touching at a point and two cubes sharing an edge, as soups: every vertex is a
  // group of copies, and those where the parts touch would be non-manifold merged. They split
  // into one vertex per part there, and every other group merges, so that each part is closed
  // (keeping the touching groups apart whole left slits around them, which split their
  // neighbours' stars in turn, until the soup of diplodocus.off was not stitched at all).
  const TriangleMesh a = icosphere(1);
  const TriangleMesh spheres =
      concatenate(a, transformed(icosphere(1), 1.0,
                                 {2 * a.vertices[0].x, 2 * a.vertices[0].y, 2 * a.vertices[0].z}));
  const TriangleMesh one = cube(1);
  const TriangleMesh cubes = concatenate(one, transformed(one, 1.0, {2, 2, 0}));
  for (const TriangleMesh& parts : {spheres, cubes}) {
    TriangleMesh indexed = parts;
    repair_mesh(indexed);  // the parts as stored: their own vertices where they touch
    TriangleMesh soup = soup_of(parts);
    const RepairReport r = repair_mesh(soup);
    const TopologyReport t = analyze_topology(soup);
    EXPECT_TRUE(t.is_manifold());
    EXPECT_EQ(t.components, 2u);
    EXPECT_EQ(t.boundary_loops, 0u);
    EXPECT_EQ(t.euler_characteristic, 4);
    EXPECT_EQ(soup.vertices.size(), indexed.vertices.size());
    EXPECT_EQ(r.duplicate_vertices_merged, 3 * parts.triangles.size() - indexed.vertices.size());
    EXPECT_GT(r.duplicate_vertices_kept_apart, 0u);
  }
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
  const TriangleMesh given = soup;
  std::vector<Index> new_id;
  const RepairReport r = repair_mesh(soup, &new_id);
  ASSERT_EQ(new_id.size(), given.vertices.size());
  for (Index v = 0; v < given.vertices.size(); ++v)  // each corner to the vertex it became
    EXPECT_EQ(soup.vertices[new_id[v]], given.vertices[v]);
  EXPECT_EQ(r.duplicate_vertices_merged, 3 * indexed.triangles.size() - indexed.vertices.size());
  EXPECT_EQ(soup.vertices.size(), indexed.vertices.size());
  const TopologyReport t = analyze_topology(soup);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_NEAR(surface_area(soup), surface_area(indexed), 1e-12);
}

// A soup of `mesh`'s triangles whose copies of each vertex differ by `offset` times a per-copy
// factor in -1..1, as a CAD exporter's rounding leaves them: every copy at its own position.
TriangleMesh cracked_soup(const TriangleMesh& mesh, double offset) {
  TriangleMesh soup;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Index base = static_cast<Index>(soup.vertices.size());
    for (const Vec3& p : mesh.corners(t)) {
      const double f = static_cast<double>(soup.vertices.size() % 7) / 3 - 1;
      soup.vertices.push_back(p + Vec3{f * offset, -f * offset, 0.5 * f * offset});
    }
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  return soup;
}

TEST(Repair, MergesCopiesOfAVertexThatDifferByRounding) {
  // A cube exported with coordinates off by up to 2e-16 (where 0 or 1 was meant) is closed once
  // its copies merge: no crack along its edges, the same area. As it is, it is 108 triangles
  // apart (a cube(3) has 108).
  const TriangleMesh box = cube(3);
  TriangleMesh soup = cracked_soup(box, 2e-16);
  ASSERT_EQ(analyze_topology(soup).components, box.triangles.size());
  const RepairReport r = repair_mesh(soup);
  EXPECT_EQ(soup.vertices.size(), box.vertices.size());
  EXPECT_EQ(r.duplicate_vertices_merged, 3 * box.triangles.size() - box.vertices.size());
  EXPECT_GT(r.nearly_equal_vertices_merged, r.duplicate_vertices_merged / 2);
  EXPECT_NE(r.summary().find("nearly equal"), std::string::npos);
  const TopologyReport t = analyze_topology(soup);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.boundary_loops, 0u);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_NEAR(surface_area(soup), surface_area(box), 1e-12);
}

TEST(Repair, KeepsVerticesAMillionthApartAndNearCopiesWhoseMergeWouldPinch) {
  // A millionth of the size is geometry, not rounding: nothing merges.
  const TriangleMesh box = cube(2);
  TriangleMesh apart = cracked_soup(box, 1e-6);
  const RepairReport far = repair_mesh(apart);
  EXPECT_EQ(far.duplicate_vertices_merged, 0u);
  EXPECT_EQ(apart.triangles.size(), box.triangles.size());
  // Two spheres touching at a point, their vertices there two units in the last place apart: a
  // merge would make a non-manifold vertex, so they stay apart, as exactly equal ones do.
  const TriangleMesh a = icosphere(1);
  const Vec3 tip = a.vertices[0];
  TriangleMesh b = transformed(icosphere(1), 1.0, 2 * tip);
  const auto touching = std::find(b.vertices.begin(), b.vertices.end(), tip);
  ASSERT_NE(touching, b.vertices.end());
  touching->x = std::nextafter(std::nextafter(tip.x, 2.0), 2.0);
  TriangleMesh both = concatenate(a, b);
  const RepairReport r = repair_mesh(both);
  EXPECT_EQ(r.duplicate_vertices_merged, 0u);
  EXPECT_EQ(r.duplicate_vertices_kept_apart, 1u);
  EXPECT_TRUE(analyze_topology(both).is_manifold());
  EXPECT_EQ(analyze_topology(both).components, 2u);
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

TEST(Repair, SplitsOutCapsThatStitchATJunctionAndKeepsTheSurfaceClosed) {
  // Dropped, the caps would leave a slit: a boundary loop the closed box never had.
  for (const int points : {1, 3}) {
    TriangleMesh m = with_t_junction(cube(4), 7, points);
    ASSERT_EQ(analyze_topology(m).boundary_loops, 0u);
    const RepairReport r = repair_mesh(m);
    EXPECT_EQ(r.caps_split, static_cast<std::size_t>(points));
    EXPECT_EQ(r.degenerate_triangles_removed, 0u);
    EXPECT_NE(r.summary().find("zero-area triangles split out"), std::string::npos);
    const TopologyReport t = analyze_topology(m);
    EXPECT_TRUE(t.is_manifold());
    EXPECT_EQ(t.components, 1u);
    EXPECT_EQ(t.boundary_loops, 0u);
    EXPECT_EQ(t.euler_characteristic, 2);
    EXPECT_TRUE(triangles_to_flip(m).empty());    // the halves keep their triangle's orientation
    EXPECT_FALSE(diagnose_repairs(m).changed());  // no zero-area triangle is left
    EXPECT_NEAR(surface_area(m), surface_area(cube(4)), 1e-12);
  }
}

TEST(Repair, DropsCapsWhoseSplitWouldLeaveTheSurfaceLessManifold) {
  // Two triangles below a line and two above, joined only by a strip of zero-area triangles
  // along it: split out, the one cap with a triangle across its long edge would put a vertex
  // of the line in both parts, which touch there once the strip is dropped.
  TriangleMesh m;
  m.vertices = {{2, -1, 0},  {3, 0, 0},   {2, 0, 0},   {1, 0, 0},
                {0.5, 0, 0}, {1.5, 0, 0}, {2.5, 0, 0}, {1.5, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}, {2, 1, 6},
                 {2, 6, 4}, {4, 6, 5}, {5, 6, 7}, {4, 5, 7}};
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.caps_split, 0u);
  EXPECT_EQ(r.degenerate_triangles_removed, 4u);
  EXPECT_TRUE(analyze_topology(m).is_manifold());
}

TEST(Repair, DropsACapWhoseLongEdgeHasNoOtherTriangle) {
  // On the boundary, dropping it opens nothing: the loop runs along its two short edges instead.
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}};
  m.triangles = {{0, 2, 3}, {2, 1, 3}, {0, 1, 2}};
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.caps_split, 0u);
  EXPECT_EQ(r.degenerate_triangles_removed, 1u);
  EXPECT_EQ(analyze_topology(m).boundary_loops, 1u);
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

// cube(n)'s triangles of the face at x = 1 (all of their corners there), listed the other way
// round.
TriangleMesh cube_with_face_flipped(int n) {
  TriangleMesh m = cube(n);
  for (Triangle& t : m.triangles)
    if (std::all_of(t.begin(), t.end(), [&](Index v) { return m.vertices[v].x == 1; }))
      std::swap(t[1], t[2]);
  return m;
}

TEST(Repair, FlipsTheTrianglesListedTheOtherWayRoundFromMostOfTheirPatch) {
  TriangleMesh m = cube_with_face_flipped(2);
  ASSERT_FALSE(analyze_topology(m).consistently_oriented);
  const std::vector<Vec3> vertices = m.vertices;
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.triangles_flipped, 8u);  // the face's 2 × 2 quads, not the other five faces
  EXPECT_NE(r.summary().find("8 triangles flipped"), std::string::npos);
  EXPECT_TRUE(analyze_topology(m).consistently_oriented);
  EXPECT_EQ(m.vertices, vertices);
  EXPECT_EQ(m.triangles, cube(2).triangles);  // as the cube was, outward
}

TEST(Repair, AMajorityListedTheOtherWayRoundKeepsItsOrientation) {
  // Every face but x = 1 flipped: those five are the majority, and the one face flips to them.
  TriangleMesh m = cube(2);
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  TriangleMesh expected = m;
  m = cube_with_face_flipped(2);
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  EXPECT_EQ(repair_mesh(m).triangles_flipped, 8u);
  EXPECT_EQ(m.triangles, expected.triangles);
}

TEST(Repair, ANonOrientableSurfaceIsLeftAsItIs) {
  TriangleMesh m = moebius_strip(12);
  const TriangleMesh before = m;
  EXPECT_EQ(repair_mesh(m).triangles_flipped, 0u);
  EXPECT_EQ(m.triangles, before.triangles);
}

TEST(Repair, DropsUnreferencedVerticesAndRenumbers) {
  TriangleMesh m;
  m.vertices = {{9, 9, 9}, {0, 0, 0}, {8, 8, 8}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{1, 3, 4}};
  std::vector<Index> new_id;
  const RepairReport r = repair_mesh(m, &new_id);
  EXPECT_EQ(new_id, (std::vector<Index>{kRemovedVertex, 0, kRemovedVertex, 1, 2}));
  EXPECT_EQ(edges_after_repair({{1, 3}, {4, 3}}, new_id), (std::vector<Edge>{{0, 1}, {1, 2}}));
  EXPECT_THROW(edges_after_repair({{0, 1}}, new_id), InvalidArgument);  // a removed vertex
  EXPECT_THROW(edges_after_repair({{1, 5}}, new_id), InvalidArgument);  // out of range
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
