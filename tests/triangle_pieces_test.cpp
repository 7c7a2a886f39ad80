// Input triangles far larger than the cells, cut into pieces for local Lloyd steps: the pieces
// tile the triangle, those a ball reaches cover the triangle's part in it, the density stays
// linear, and an RVD over the pieces has the cells of the RVD over the triangle.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "cvt/triangle_pieces.hpp"
#include "cvtmesh/rvd.hpp"
#include "cvtmesh/rvd_consumers.hpp"

namespace cvtmesh {
namespace {

// One triangle 4 × 3 long, tilted out of every coordinate plane, and a small one beside it.
TriangleMesh big_and_small() {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {4, 0.5, 0.3}, {0.7, 3, -0.4}, {5, 5, 5}, {5.1, 5, 5}, {5, 5.1, 5}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  return m;
}

constexpr double kSpacing = 0.1;

std::vector<double> piece_areas(const TriangleMesh& patch) {
  std::vector<double> out;
  for (std::size_t t = 0; t < patch.triangles.size(); ++t) {
    const auto [a, b, c] = patch.corners(t);
    out.push_back(triangle_area(a, b, c));
  }
  return out;
}

Vec3 normal_of(const TriangleMesh& m, std::size_t t) {
  const auto [a, b, c] = m.corners(t);
  return cross(b - a, c - a);
}

// Whether p (in the triangle's plane) lies in triangle t of m, up to rounding.
bool inside(const TriangleMesh& m, std::size_t t, const Vec3& p) {
  const auto [a, b, c] = m.corners(t);
  const Vec3 n = cross(b - a, c - a);
  const double scale = 1e-9 * dot(n, n);
  return dot(cross(b - a, p - a), n) >= -scale && dot(cross(c - b, p - b), n) >= -scale &&
         dot(cross(a - c, p - c), n) >= -scale;
}

TEST(TrianglePieces, CutsOnlyTrianglesLongerThanEightSpacings) {
  const TriangleMesh m = big_and_small();
  const TrianglePieces pieces(m, kSpacing);
  EXPECT_TRUE(pieces.cut(0));
  EXPECT_FALSE(pieces.cut(1));
  EXPECT_FALSE(TrianglePieces(m, 0.6).cut(0));  // 4.04 long: within 8 spacings of 0.6
  EXPECT_TRUE(TrianglePieces(m, 0.4).cut(0));
  // No spacing to cut to (a surface without area, no seed): nothing is cut.
  EXPECT_FALSE(TrianglePieces(m, 0.0).cut(0));
  EXPECT_FALSE(TrianglePieces(m, std::numeric_limits<double>::infinity()).cut(0));
}

// Longest-edge bisection cuts a sliver across: pieces as long as allowed, not k² thinner slivers.
TEST(TrianglePieces, CutsASliverAcross) {
  TriangleMesh sliver;
  sliver.vertices = {{0, 0, 0}, {4, 0, 0}, {2, 0.05, 0}};
  sliver.triangles = {{0, 1, 2}};
  const TrianglePieces pieces(sliver, kSpacing);
  ASSERT_TRUE(pieces.cut(0));
  const Ball everything{{0, 0, 0}, 10};
  TriangleMesh patch;
  std::vector<double> unused;
  pieces.add_pieces(0, std::span(&everything, 1), nullptr, patch, unused);
  // 4 long in pieces at most 0.4 long: 10 along it at least; a lattice of 10 parts an edge
  // would make 100.
  EXPECT_GE(patch.triangles.size(), 10u);
  EXPECT_LE(patch.triangles.size(), 64u);
}

TEST(TrianglePieces, AllPiecesTileTheTriangleInItsOrientation) {
  const TriangleMesh m = big_and_small();
  const TrianglePieces pieces(m, kSpacing);
  const Ball everything{{0, 0, 0}, 10};
  TriangleMesh patch;
  std::vector<double> density;
  pieces.add_pieces(0, std::span(&everything, 1), nullptr, patch, density);
  EXPECT_TRUE(density.empty());
  const auto [a, b, c] = m.corners(0);
  double sum = 0;
  for (const double area : piece_areas(patch)) {
    EXPECT_GT(area, 0);
    sum += area;
  }
  EXPECT_NEAR(sum, triangle_area(a, b, c), 1e-12 * triangle_area(a, b, c));
  for (std::size_t t = 0; t < patch.triangles.size(); ++t) {
    EXPECT_GT(dot(normal_of(patch, t), normal_of(m, 0)), 0) << "piece " << t << " flipped";
    const auto [p, q, r] = patch.corners(t);
    EXPECT_LE(std::max({distance(p, q), distance(q, r), distance(r, p)}), 4 * kSpacing + 1e-12);
  }
  // The triangle's corners are among the pieces' vertices, bit for bit.
  for (const Vec3& corner : {a, b, c})
    EXPECT_NE(std::find(patch.vertices.begin(), patch.vertices.end(), corner),
              patch.vertices.end());
}

TEST(TrianglePieces, PiecesABallReachesCoverTheTriangleInIt) {
  const TriangleMesh m = big_and_small();
  const TrianglePieces pieces(m, kSpacing);
  const auto [a, b, c] = m.corners(0);
  const Ball ball{(1.0 / 3) * (a + b + c), 0.4};
  TriangleMesh all, near;
  std::vector<double> unused;
  const Ball everything{{0, 0, 0}, 10};
  pieces.add_pieces(0, std::span(&everything, 1), nullptr, all, unused);
  pieces.add_pieces(0, std::span(&ball, 1), nullptr, near, unused);
  EXPECT_GT(near.triangles.size(), 0u);
  EXPECT_LT(4 * near.triangles.size(), all.triangles.size());
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  int tried = 0;
  while (tried < 500) {
    double u = unit(random), v = unit(random);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vec3 p = a + u * (b - a) + v * (c - a);
    if (distance(p, ball.center) > ball.radius) continue;
    ++tried;
    bool covered = false;
    for (std::size_t t = 0; t < near.triangles.size() && !covered; ++t)
      covered = inside(near, t, p);
    EXPECT_TRUE(covered) << "a point of the ball in no piece: " << p.x << " " << p.y << " " << p.z;
  }
}

TEST(TrianglePieces, DensityIsLinearOverTheTriangle) {
  const TriangleMesh m = big_and_small();
  const TrianglePieces pieces(m, kSpacing);
  // ρ = 1 + x + 2y - z at the vertices: linear over the triangle, so at every piece vertex.
  std::vector<double> rho;
  for (const Vec3& v : m.vertices) rho.push_back(1 + v.x + 2 * v.y - v.z);
  const Ball everything{{0, 0, 0}, 10};
  TriangleMesh patch;
  std::vector<double> density;
  pieces.add_pieces(0, std::span(&everything, 1), &rho, patch, density);
  ASSERT_EQ(density.size(), patch.vertices.size());
  for (std::size_t v = 0; v < density.size(); ++v) {
    const Vec3& p = patch.vertices[v];
    EXPECT_NEAR(density[v], 1 + p.x + 2 * p.y - p.z, 1e-12);
  }
}

// The pieces stand for the triangle in an RVD: every cell has the same mass and centroid.
TEST(TrianglePieces, CellsOverThePiecesAreTheCellsOverTheTriangle) {
  TriangleMesh m = big_and_small();
  m.triangles.pop_back();
  const auto [a, b, c] = m.corners(0);
  std::vector<Vec3> seeds;
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(0, 1);
  const Vec3 n = normal_of(m, 0);
  for (int k = 0; k < 60; ++k) {
    double u = unit(random), v = unit(random);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    // Off the plane a little either side, as seeds of a curved surface are.
    seeds.push_back(a + u * (b - a) + v * (c - a) + (0.02 * (unit(random) - 0.5)) * n);
  }
  const TrianglePieces pieces(m, kSpacing);
  const Ball everything{{0, 0, 0}, 10};
  TriangleMesh cut;
  std::vector<double> unused;
  pieces.add_pieces(0, std::span(&everything, 1), nullptr, cut, unused);

  const auto integrals = [&](const TriangleMesh& surface) {
    const RestrictedVoronoiDiagram rvd(surface, seeds);
    CellIntegrator integrator(rvd);
    PolygonSink* sinks[] = {&integrator};
    rvd.traverse(sinks);
    return integrator.result();
  };
  const CellIntegrals whole = integrals(m), in_pieces = integrals(cut);
  for (Index s = 0; s < seeds.size(); ++s) {
    EXPECT_NEAR(in_pieces.mass[s], whole.mass[s], 1e-12 * whole.total_mass) << "seed " << s;
    if (whole.mass[s] > 0) {
      EXPECT_LT(distance(in_pieces.centroid(s), whole.centroid(s)), 1e-10) << "seed " << s;
    }
  }
}

}  // namespace
}  // namespace cvtmesh
