// Groups of nearly equal points (geometry/near_points): what repair merges as one vertex.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/near_points.hpp"

namespace cvtmesh {
namespace {

TEST(NearPoints, GroupsCopiesThatDifferByRoundingAndNothingFarther) {
  // cos(π/2) written two ways (6.1e-17 and 6e-17 where 0 was meant), an exact copy, a point a
  // millionth away (real geometry), and a far one.
  const std::vector<Vec3> points = {{6.123e-17, 0.2, 0.21875}, {1, 1, 1},
                                    {5.995e-17, 0.2, 0.21875}, {0, 0.2, 0.21875},
                                    {1e-6, 0.2, 0.21875},      {1, 1, 1}};
  const double tolerance = near_point_tolerance(points);
  EXPECT_GT(tolerance, 1e-16);
  EXPECT_LT(tolerance, 1e-11);
  EXPECT_EQ(near_point_groups(points, tolerance), (std::vector<Index>{0, 1, 0, 0, 4, 1}));
  // With no tolerance, equal points only.
  EXPECT_EQ(near_point_groups(points, 0), (std::vector<Index>{0, 1, 2, 3, 4, 1}));
}

TEST(NearPoints, FindsPairsAcrossTheSidesOfItsCells) {
  // The search cells are 1000 tolerances wide: pairs that straddle a side, an edge or a corner
  // of a cell, in every direction, are grouped all the same; pairs just over the tolerance are not.
  const double tolerance = 1e-3;
  const double side = 1000 * tolerance;  // a cell side lies at every multiple of it
  std::vector<Vec3> points;
  std::vector<Index> expected;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        // A corner of its own for each direction, two cells from the last.
        const Vec3 corner{2.0 * side * static_cast<double>(points.size()), -2 * side, 5 * side};
        const Vec3 step{dx * 0.25 * tolerance, dy * 0.25 * tolerance, dz * 0.25 * tolerance};
        const Index first = static_cast<Index>(points.size());
        points.push_back(corner + step);
        points.push_back(corner - step);
        expected.push_back(first);
        expected.push_back(first);
        if (dx == 0 && dy == 0 && dz == 0) continue;  // equal points
        // 1.01 tolerances apart across the same sides: apart.
        const Vec3 far = (1.01 * tolerance / (2 * norm(step))) * step;
        points.push_back(corner + far + Vec3{0, 10 * side, 0});
        points.push_back(corner - far + Vec3{0, 10 * side, 0});
        expected.push_back(first + 2);
        expected.push_back(first + 3);
      }
  EXPECT_EQ(near_point_groups(points, tolerance), expected);
}

TEST(NearPoints, AChainOfNearPointsIsOneGroup) {
  const double tolerance = 1e-9;
  std::vector<Vec3> points;
  for (int k = 0; k < 50; ++k) points.push_back({0.9 * tolerance * k, 1, 1});
  const std::vector<Index> groups = near_point_groups(points, tolerance);
  for (const Index g : groups) EXPECT_EQ(g, 0u);
}

}  // namespace
}  // namespace cvtmesh
