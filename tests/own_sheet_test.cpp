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

}  // namespace
}  // namespace cvtmesh
