// Vertices back onto their own sheet (finish/own_sheet): beside a sharp edge whose faces meet at
// a narrow angle, a vertex on one face whose triangles follow the other moves onto the other.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "finish/own_sheet.hpp"
#include "geometry/surface_projector.hpp"

namespace cvtmesh {
namespace {

constexpr double kAlpha = 40 * std::numbers::pi / 180;  // the wedge's angle at its edge

// Two faces meeting along the x axis at kAlpha: the lower in z = 0 (normal -z), the upper
// rising from the axis (normal (0, -sin, cos)), each a rectangle 2 long and 2 wide, their normals
// pointing out of the wedge between them.
TriangleMesh wedge() {
  const Vec3 up{0, std::cos(kAlpha), std::sin(kAlpha)};
  TriangleMesh m;
  m.vertices = {{-1, 0, 0},
                {1, 0, 0},
                {-1, 2, 0},
                {1, 2, 0},
                Vec3{-1, 0, 0} + 2 * up,
                Vec3{1, 0, 0} + 2 * up};
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {0, 1, 4}, {1, 5, 4}};
  return m;
}

Vec3 upper_normal() {
  return {0, -std::sin(kAlpha), std::cos(kAlpha)};
}

// Six vertices round the upper face's point 1 away from the edge (0.2 away from it, in its
// plane), and vertex 6 joined to them all, at `centre`; the triangles face as the upper face
// does, or the other way.
TriangleMesh fan_at(const Vec3& centre, bool facing_up = true) {
  const Vec3 along{1, 0, 0}, across{0, std::cos(kAlpha), std::sin(kAlpha)};
  TriangleMesh m;
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3;
    m.vertices.push_back(across + 0.2 * (std::cos(a) * along + std::sin(a) * across));
  }
  m.vertices.push_back(centre);
  for (Index k = 0; k < 6; ++k) {
    const Index next = (k + 1) % 6;
    m.triangles.push_back(facing_up ? Triangle{6, k, next} : Triangle{6, next, k});
  }
  return m;
}

double above_upper_face(const Vec3& p) {
  return dot(upper_normal(), p);
}

TEST(OwnSheet, MovesAVertexOnTheLowerFaceOntoTheUpperWhoseTrianglesItServes) {
  const SurfaceProjector surface(wedge());
  // Below the ring's middle, on the lower face: its triangles face the upper face's way.
  TriangleMesh m = fan_at({0, std::cos(kAlpha), 0});
  ASSERT_GT(std::abs(above_upper_face(m.vertices[6])), 0.4);
  const TriangleMesh before = m;
  EXPECT_EQ(move_onto_own_sheet(m, surface, std::vector<bool>(7, true)), 1u);
  EXPECT_NEAR(above_upper_face(m.vertices[6]), 0, 1e-9);
  EXPECT_EQ(m.triangles, before.triangles);
  for (Index v = 0; v < 6; ++v) EXPECT_EQ(m.vertices[v], before.vertices[v]);
}

TEST(OwnSheet, LeavesAVertexThatIsNotMovableOrWhoseNeighboursAreAllOnCurves) {
  const SurfaceProjector surface(wedge());
  TriangleMesh pinned = fan_at({0, std::cos(kAlpha), 0});
  std::vector<bool> movable(7, true);
  movable[6] = false;
  EXPECT_EQ(move_onto_own_sheet(pinned, surface, movable), 0u);
  // Neighbours on curves stand between sheets: none shows which sheet is the vertex's own.
  TriangleMesh ringed = fan_at({0, std::cos(kAlpha), 0});
  std::vector<bool> centre_only(7, false);
  centre_only[6] = true;
  EXPECT_EQ(move_onto_own_sheet(ringed, surface, centre_only), 0u);
}

TEST(OwnSheet, LeavesAVertexWhoseOwnSheetIsUnderHalfAnEdgeAway) {
  const SurfaceProjector surface(wedge());
  // On the lower face near the edge: the upper face is about 0.1 away along the normal, under
  // half the vertex's shortest edge (a fold or a crossing of the input looks like this).
  TriangleMesh m = fan_at({0, 0.15, 0});
  EXPECT_EQ(move_onto_own_sheet(m, surface, std::vector<bool>(7, true)), 0u);
}

// A square sheet facing +z at z = 0; a small patch facing -z at z = -0.4, under the square's
// middle; given `tab`, another small patch facing +z below it, at z = -0.75. Each patch is 0.04
// wide.
TriangleMesh plate_over_patches(bool tab) {
  TriangleMesh m;
  const auto square = [&m](double half, double z, bool up) {
    const auto first = static_cast<Index>(m.vertices.size());
    m.vertices.insert(m.vertices.end(),
                      {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}});
    const Index a = first, b = first + 1, c = first + 2, d = first + 3;
    if (up)
      m.triangles.insert(m.triangles.end(), {{a, b, c}, {a, c, d}});
    else
      m.triangles.insert(m.triangles.end(), {{a, c, b}, {a, d, c}});
  };
  square(1, 0, true);
  square(0.02, -0.4, false);
  if (tab) square(0.02, -0.75, true);
  return m;
}

// Six vertices on a circle of radius 0.5 in z = 0, and vertex 6 at `centre` joined to them all,
// the triangles facing +z.
TriangleMesh ring_over(const Vec3& centre) {
  TriangleMesh m;
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3;
    m.vertices.push_back({0.5 * std::cos(a), 0.5 * std::sin(a), 0});
  }
  m.vertices.push_back(centre);
  for (Index k = 0; k < 6; ++k) m.triangles.push_back({6, k, (k + 1) % 6});
  return m;
}

TEST(OwnSheet, KeepsAMoveOnlyWhereItBringsTheVertexsTrianglesNearerTheInput) {
  // The centre stands on the patch facing -z, its triangles face +z, and its neighbours stand
  // on the sheet facing +z: it faces away, and its own sheet is 0.4 above it.
  TriangleMesh alone = ring_over({0, 0, -0.4});
  EXPECT_EQ(move_onto_own_sheet(alone, SurfaceProjector(plate_over_patches(false)),
                                std::vector<bool>(7, true)),
            1u);
  EXPECT_NEAR(alone.vertices[6].z, 0, 1e-12);
  // A patch facing +z 0.35 below it is nearer along the line than the sheet: moving there
  // would take the farthest of its triangles' centroids and edge midpoints from 0.2 off the
  // input to 0.25, so it stays.
  TriangleMesh tabbed = ring_over({0, 0, -0.4});
  EXPECT_EQ(move_onto_own_sheet(tabbed, SurfaceProjector(plate_over_patches(true)),
                                std::vector<bool>(7, true)),
            0u);
  EXPECT_EQ(tabbed.vertices[6].z, -0.4);
}

}  // namespace
}  // namespace cvtmesh
