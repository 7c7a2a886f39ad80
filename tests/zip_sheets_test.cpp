// Zipping sheets remeshed apart (remesh/zip_sheets): along the junction where they meet, every
// sheet gets the positions of all; one sheet's position a little beside another's is that one,
// not a second position an edge of a fiftieth of the others away.
#include <gtest/gtest.h>

#include <optional>
#include <utility>
#include <vector>

#include "remesh/zip_sheets.hpp"

namespace cvtmesh {
namespace {

// A strip of triangles on one side of the junction from (0, 0, 0) to (1, 0, 0): its vertices on
// the junction at `xs` (0 and 1 among them), then a vertex `side` away beside each step's middle.
void add_sheet(TriangleMesh& m, const std::vector<double>& xs, const Vec3& side) {
  const auto first = static_cast<Index>(m.vertices.size());
  for (const double x : xs) m.vertices.push_back({x, 0, 0});
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    m.vertices.push_back(Vec3{0.5 * (xs[i] + xs[i + 1]), 0, 0} + side);
    const auto a = static_cast<Index>(first + i), apex = static_cast<Index>(m.vertices.size() - 1);
    m.triangles.push_back({a, static_cast<Index>(a + 1), apex});
  }
}

// Two sheets on the junction, the first's vertices there at `first`, the second's at `second`,
// zipped: the mesh, where the second sheet's vertices start, how many vertices it had, and the
// zip's (key, vertex) pairs.
struct Zipped {
  TriangleMesh mesh;
  Index second = 0;
  std::size_t before = 0;
  std::optional<std::vector<std::pair<Index, Index>>> keyed;
};

Zipped zipped(const std::vector<double>& first, const std::vector<double>& second) {
  Zipped z;
  add_sheet(z.mesh, first, {0, 0.25, 0});
  z.second = static_cast<Index>(z.mesh.vertices.size());
  add_sheet(z.mesh, second, {0, 0, 0.25});
  z.before = z.mesh.vertices.size();
  const std::vector<SheetVertices> sheets{{0, z.second}, {z.second, static_cast<Index>(z.before)}};
  const std::vector<SharedSegment> segments{{{{0, 0, 0}, {1, 0, 0}}, {0, 1}}};
  std::vector<Edge> feature_edges;
  z.keyed = zip_shared_segments(z.mesh, feature_edges, sheets, segments, 0);
  return z;
}

TEST(ZipSheets, APositionBesideAnothersJoinsItInsteadOfAddingOne) {
  const Zipped z = zipped({0, 0.25, 0.5, 0.75, 1}, {0, 0.25, 0.51, 0.75, 1});
  ASSERT_TRUE(z.keyed.has_value());
  EXPECT_EQ(z.mesh.vertices.size(), z.before);  // nothing added: each sheet has every position
  EXPECT_EQ(z.mesh.vertices[z.second + 2], (Vec3{0.5, 0, 0}));  // moved onto the first sheet's
  // The three inner positions, each in both sheets.
  EXPECT_EQ(z.keyed->size(), 6u);
  for (const auto& [key, vertex] : *z.keyed)
    EXPECT_TRUE(z.mesh.vertices[vertex].x == 0.25 || z.mesh.vertices[vertex].x == 0.5 ||
                z.mesh.vertices[vertex].x == 0.75);
}

TEST(ZipSheets, PositionsFarApartGoIntoEverySheet) {
  const Zipped z = zipped({0, 0.5, 1}, {0, 0.25, 1});
  ASSERT_TRUE(z.keyed.has_value());
  EXPECT_EQ(z.mesh.vertices.size(), z.before + 2);  // 0.25 into the first, 0.5 into the second
  EXPECT_EQ(z.keyed->size(), 4u);
}

}  // namespace
}  // namespace cvtmesh
