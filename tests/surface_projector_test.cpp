// The nearest surface points that CCVT, shape improvement, the fit and the Hausdorff report
// project onto: the nearest of all triangles, from any hint, on fine and coarse surfaces and
// between two sheets close together; and where a line meets the surface (the fit).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "cvtmesh/rvd_consumers.hpp"
#include "geometry/surface_projector.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
  return distance(p, a + t * ab);
}

// By brute force: inside the triangle's prism, the distance to its plane; else to its edges.
double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(b - a, c - a);
  const bool inside = dot(cross(b - a, p - a), n) >= 0 && dot(cross(c - b, p - b), n) >= 0 &&
                      dot(cross(a - c, p - c), n) >= 0;
  if (inside) return std::abs(dot(p - a, n)) / norm(n);
  return std::min(
      {distance_to_segment(p, a, b), distance_to_segment(p, b, c), distance_to_segment(p, c, a)});
}

double distance_to_mesh(const TriangleMesh& mesh, const Vec3& p) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    d = std::min(d, distance_to_triangle(p, a, b, c));
  }
  return d;
}

// Random points in the box around the mesh, grown by `margin`.
std::vector<Vec3> points_around(const TriangleMesh& mesh, double margin, std::size_t n) {
  Vec3 lo = mesh.vertices[0], hi = lo;
  for (const Vec3& v : mesh.vertices) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> points(n);
  for (Vec3& p : points)
    p = {lo.x - margin + u(random) * (hi.x - lo.x + 2 * margin),
         lo.y - margin + u(random) * (hi.y - lo.y + 2 * margin),
         lo.z - margin + u(random) * (hi.z - lo.z + 2 * margin)};
  return points;
}

// Every foot is the nearest point of the surface (up to rounding), on the triangle it names,
// whose unit normal it carries; and a hint anywhere on the surface finds the same distance.
void expect_nearest(const TriangleMesh& mesh, const std::vector<Vec3>& points) {
  const SurfaceProjector surface(mesh);
  const SurfaceProjector::Foot far_hint = surface.nearest(points.back());
  for (const Vec3& p : points) {
    const double expected = distance_to_mesh(mesh, p);
    const SurfaceProjector::Foot foot = surface.nearest(p);
    EXPECT_NEAR(distance(p, foot.point), expected, 1e-12);
    EXPECT_NEAR(distance(p, surface.nearest(p, far_hint).point), expected, 1e-12);
    const auto [a, b, c] = mesh.corners(surface.surface_triangle(foot.triangle));
    EXPECT_NEAR(distance_to_triangle(foot.point, a, b, c), 0, 1e-12);
    const Vec3 n = cross(b - a, c - a);
    EXPECT_NEAR(dot(foot.normal, (1 / norm(n)) * n), 1, 1e-12);
    EXPECT_NEAR(surface.squared_distance_to(p, foot.triangle), expected * expected, 1e-12);
    // A triangle within a reach a little over the distance, at its squared distance; none
    // within a little under it (for a point off the surface).
    const double over = (1 + 1e-6) * expected + 1e-12;
    const std::optional<SurfaceProjector::Near> near = surface.within(p, over * over);
    ASSERT_TRUE(near.has_value());
    EXPECT_LE(near->squared, over * over);
    EXPECT_EQ(near->squared, surface.squared_distance_to(p, near->triangle));
    const double under = (1 - 1e-6) * expected;
    if (expected > 1e-9) {
      EXPECT_FALSE(surface.within(p, under * under).has_value());
      EXPECT_FALSE(surface.within(p, under * under, foot.triangle).has_value());
    }
    // A hint, near or far, changes whether one is found no more than the distance does.
    for (const std::size_t hint : {foot.triangle, far_hint.triangle}) {
      const std::optional<SurfaceProjector::Near> hinted = surface.within(p, over * over, hint);
      ASSERT_TRUE(hinted.has_value());
      EXPECT_LE(hinted->squared, over * over);
      EXPECT_EQ(hinted->squared, surface.squared_distance_to(p, hinted->triangle));
    }
  }
}

TEST(SurfaceProjector, FindsTheNearestPointOfAFineSurface) {
  const TriangleMesh ring = torus(1.0, 0.3, 48, 16);
  expect_nearest(ring, points_around(ring, 0.2, 400));
}

TEST(SurfaceProjector, FindsTheNearestPointOfACoarseSurface) {
  // 12 triangles, each far larger than the distances asked about.
  const TriangleMesh box = cube(1);
  expect_nearest(box, points_around(box, 0.5, 400));
}

// Two unit squares, at z = 0 and z = 1e-3.
TriangleMesh two_sheets() {
  TriangleMesh sheets;
  for (const double z : {0.0, 1e-3}) {
    const auto base = static_cast<Index>(sheets.vertices.size());
    sheets.vertices.insert(sheets.vertices.end(), {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}});
    add_quad(sheets, base, base + 1, base + 2, base + 3);
  }
  return sheets;
}

TEST(SurfaceProjector, TellsTwoSheetsCloseTogetherApart) {
  // The points between and around them.
  const TriangleMesh sheets = two_sheets();
  std::vector<Vec3> points = points_around(sheets, 1e-3, 300);
  for (std::size_t k = 0; k < 100; ++k)
    points.push_back({0.01 * static_cast<double>(k), 0.5, 1e-3 * static_cast<double>(k % 5) / 4});
  expect_nearest(sheets, points);
}

// along: the crossing of the line nearest to the point, within reach, in either direction.
TEST(SurfaceProjector, FindsTheSurfaceAlongALine) {
  const TriangleMesh unit = transformed(cube(1), 0.5, {0.5, 0.5, 0.5});  // [0, 1]^3
  const SurfaceProjector box(unit);
  const Vec3 up{0, 0, 1};
  // Inside, 0.1 below the top face and 0.9 above the bottom one: up to the top.
  EXPECT_NEAR(box.along({0.3, 0.4, 0.9}, up, 0.5).value(), 0.1, 1e-12);
  // Outside, above the top: down to it, a negative step along `up`.
  EXPECT_NEAR(box.along({0.3, 0.4, 1.2}, up, 0.5).value(), -0.2, 1e-12);
  // Out of reach both ways, or parallel to the faces it runs between: none.
  EXPECT_FALSE(box.along({0.3, 0.4, 0.5}, up, 0.4).has_value());
  EXPECT_FALSE(box.along({0.3, 0.4, 0.5}, (1 / std::sqrt(2.0)) * Vec3{1, 1, 0}, 0.2).has_value());
  // Slanted towards a corner: out through the face y = 1 (0.05 away in y; x and z are 0.1 and 0.2
  // from theirs), the way back out of reach.
  const Vec3 p{0.9, 0.95, 0.8}, d = (1 / std::sqrt(3.0)) * Vec3{1, 1, 1};
  const double t = box.along(p, d, 1).value();
  EXPECT_NEAR(distance_to_mesh(unit, p + t * d), 0, 1e-12);
  EXPECT_NEAR(t, 0.05 * std::sqrt(3.0), 1e-12);
}

TEST(SurfaceProjector, AlongALineTakesTheNearerOfTwoSheets) {
  const SurfaceProjector surface(two_sheets());
  EXPECT_NEAR(surface.along({0.5, 0.5, 0.3e-3}, {0, 0, 1}, 1).value(), -0.3e-3, 1e-15);
  EXPECT_NEAR(surface.along({0.5, 0.5, 0.7e-3}, {0, 0, 1}, 1).value(), 0.3e-3, 1e-15);
}

// The projector shares its unit normals with the CVT integrals where it holds every triangle:
// they must be cvtmesh::unit_normals of the surface to the bit, by surface id. With a triangle
// without area among others, it leaves that one out, and has none to share.
TEST(SurfaceProjector, SharesTheSurfacesUnitNormalsOnlyWhereItHoldsEveryTriangle) {
  const TriangleMesh sphere = icosphere(3);
  const SurfaceProjector whole(sphere);
  const std::vector<Vec3> expected = unit_normals(sphere);
  const std::span<const Vec3> shared = whole.unit_normals();
  ASSERT_EQ(shared.size(), expected.size());
  EXPECT_TRUE(std::equal(shared.begin(), shared.end(), expected.begin()));

  TriangleMesh with_flat = sphere;
  const Triangle first = with_flat.triangles[0];
  with_flat.triangles.push_back({first[0], first[1], first[1]});  // no area
  const SurfaceProjector partial(with_flat);
  EXPECT_TRUE(partial.unit_normals().empty());
  // The triangles it holds are numbered on: the flat one, last, is not among them.
  const SurfaceProjector::Foot foot = partial.nearest(1.5 * sphere.vertices[first[0]]);
  EXPECT_LT(partial.surface_triangle(foot.triangle), sphere.triangles.size());
}

}  // namespace
}  // namespace cvtmesh
