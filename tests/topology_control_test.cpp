// Topology control of the output (paper §4.4): cells in several pieces are found, and feature
// curves cut by a third cell get a seed of their own there.
#include <gtest/gtest.h>

#include <algorithm>

#include "cvt/cell_islands.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/topology.hpp"
#include "cvtmesh/features.hpp"
#include "features/curve_projector.hpp"
#include "features/feature_seeds.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// The box [-1,1]² × [-0.01,0.01]: a thin plate, closed.
TriangleMesh thin_plate() {
  TriangleMesh m = cube(8);
  for (Vec3& v : m.vertices) v.z *= 0.01;
  return m;
}

TEST(CellIslands, ASeedOverAThinPlateOwnsAPieceOfTheFarFace) {
  // One seed over the middle of the top face, eight around the bottom face's rim: the rim
  // seeds own the plate's sides, so the middle seed's cell is a piece on top and one below.
  std::vector<Vec3> seeds{{0, 0, 0.01}};
  for (int k = 0; k < 8; ++k)
    seeds.push_back({0.9 * std::cos(k * M_PI / 4), 0.9 * std::sin(k * M_PI / 4), -0.01});
  const std::vector<CellIsland> islands = cell_islands(thin_plate(), seeds);
  ASSERT_EQ(islands.size(), 1u);
  EXPECT_EQ(islands[0].seed, 0u);
  // The smaller piece is the far one, below, around the middle.
  EXPECT_DOUBLE_EQ(islands[0].centroid.z, -0.01);
  EXPECT_LT(std::abs(islands[0].centroid.x) + std::abs(islands[0].centroid.y), 0.05);
  EXPECT_GT(islands[0].area, 0.5);
}

TEST(CellIslands, WellSpreadSeedsHaveNone) {
  const TriangleMesh sphere = icosphere(4);
  std::vector<Vec3> seeds;
  for (std::size_t v = 0; v < sphere.vertices.size(); v += 7) seeds.push_back(sphere.vertices[v]);
  EXPECT_TRUE(cell_islands(sphere, seeds).empty());
  // Seeds on both faces of the plate, as dense as the plate is thin: every cell is one piece.
  std::vector<Vec3> dense;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j)
      dense.push_back({-0.995 + 0.01 * i, -0.995 + 0.01 * j, (i + j) % 2 ? 0.01 : -0.01});
  EXPECT_TRUE(cell_islands(thin_plate(), dense).empty());
}

TEST(MendMissingLinks, AStraySurfaceSeedJoinsTheCurveItCuts) {
  const TriangleMesh box = cube(4);
  const Features features = detect_features(box, {});
  ASSERT_EQ(features.corners.size(), 8u);
  const CurveProjector curves(box, features);
  // The corners, and one surface seed next to the middle of the first curve.
  std::vector<Vec3> seeds;
  SeedConstraints c;
  for (Index v : features.corners) {
    c.corner_seed.push_back(static_cast<Index>(seeds.size()));
    seeds.push_back(box.vertices[v]);
    c.kind.push_back(SeedConstraints::Kind::corner);
    c.curve.push_back(0);
    c.anchor.push_back(box.vertices[v]);
  }
  const Vec3 middle = curves.at(0, curves.length(0) / 2);
  const Vec3 inward = middle.x > 0 ? Vec3{-0.05, 0, 0} : Vec3{0.05, 0, 0};
  const Index stray = static_cast<Index>(seeds.size());
  seeds.push_back(middle + inward);
  c.kind.push_back(SeedConstraints::Kind::surface);
  c.curve.push_back(0);
  c.anchor.push_back({});

  const std::vector<FeatureLink> links = feature_links(seeds, c, features, curves);
  ASSERT_EQ(links.size(), 12u);  // one per edge of the cube, corner to corner
  const std::vector<FeatureLink> first(links.begin(), links.begin() + 1);
  ASSERT_EQ(first[0].curve, 0u);
  EXPECT_EQ(mend_missing_links(seeds, c, first, curves, 0.5), 1u);
  EXPECT_EQ(seeds.size(), 9u);  // the stray joined: no seed added
  EXPECT_EQ(c.kind.size(), 9u);
  EXPECT_EQ(c.kind[stray], SeedConstraints::Kind::curve);
  EXPECT_EQ(c.curve[stray], 0u);
  EXPECT_NEAR(norm(seeds[stray] - middle), 0.0, 1e-12);

  // Where no surface seed cuts a missing link, nothing moves and nothing comes in.
  const std::vector<Vec3> kept = seeds;
  EXPECT_EQ(mend_missing_links(seeds, c, {links[1]}, curves, 0.5), 0u);
  EXPECT_EQ(seeds, kept);
}

TEST(TopologyControl, AThinPlateComesOutHomeomorphic) {
  // A plate as thin as a quarter of the edge length: cells of seeds near its rim reach around
  // onto the other face. Without topology control this output is non-manifold; the control
  // adds a few seeds and it comes out with the plate's topology.
  TriangleMesh plate = cube(8);
  for (Vec3& v : plate.vertices) v.z *= 0.05;
  RemeshSettings s;
  s.vertices = 400;
  s.features.sharp_edges = false;
  const RemeshResult r = remesh(plate, s);
  const TopologyReport t = analyze_topology(r.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(same_topology(t, analyze_topology(plate)));
  EXPECT_GT(r.islands_seeded, 0u);
  EXPECT_GE(r.mend_rounds, 1);
  EXPECT_LE(r.mesh.vertices.size(), 420u);
}

}  // namespace
}  // namespace cvtmesh
