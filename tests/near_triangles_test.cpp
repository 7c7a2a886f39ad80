// The triangles a search of NearTriangles finds include every triangle whose box overlaps the
// box searched, however the vertices moved and the triangles were rewired since it was built
// (finish/near_triangles: improve_shapes's crossing checks look only at those).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "finish/near_triangles.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

struct Box {
  Vec3 lo, hi;
};

Box box_of(const TriangleMesh& m, Index t) {
  Box b{m.vertices[m.triangles[t][0]], m.vertices[m.triangles[t][0]]};
  for (const Index v : m.triangles[t]) {
    const Vec3& p = m.vertices[v];
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

bool overlap(const Box& a, const Box& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
         a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

// Every triangle not gone whose box overlaps triangle t's is found.
void expect_all_overlapping_found(const NearTriangles& near, const TriangleMesh& m,
                                  const std::vector<bool>& gone, Index t) {
  const Box query = box_of(m, t);
  std::set<Index> found;
  near.for_each_near(query.lo, query.hi, [&](Index s) { EXPECT_TRUE(found.insert(s).second); });
  for (Index s = 0; s < m.triangles.size(); ++s) {
    if (gone[s] || !overlap(box_of(m, s), query)) continue;
    EXPECT_TRUE(found.contains(s)) << "triangle " << s << " beside " << t << " not found";
  }
}

TEST(NearTriangles, FindsEveryOverlappingTriangleAfterMovesAndRewiring) {
  TriangleMesh m = testing::icosphere(3);
  std::vector<bool> gone(m.triangles.size(), false);
  NearTriangles near;
  EXPECT_TRUE(near.stale());
  near.build(m, gone);
  EXPECT_FALSE(near.stale());
  std::mt19937 rng(7);
  std::uniform_int_distribution<Index> vertex(0, static_cast<Index>(m.vertices.size() - 1));
  std::uniform_int_distribution<Index> triangle(0, static_cast<Index>(m.triangles.size() - 1));
  std::uniform_real_distribution<double> step(-0.05, 0.05);
  for (int round = 0; round < 200; ++round) {
    // A vertex moved by about a third of an edge, as a sweep's move does.
    const Index v = vertex(rng);
    m.vertices[v] += Vec3{step(rng), step(rng), step(rng)};
    near.moved(v, m.vertices[v]);
    // A triangle given another corner far off, as a collapse or a flip rewires one.
    if (round % 10 == 0) {
      const Index t = triangle(rng);
      m.triangles[t][0] = vertex(rng);
      near.rewired(t);
    }
    if (near.stale()) near.build(m, gone);
    expect_all_overlapping_found(near, m, gone, triangle(rng));
  }
}

TEST(NearTriangles, ABoxWiderThanTheGridFindsEveryTriangle) {
  const TriangleMesh m = testing::icosphere(2);
  const std::vector<bool> gone(m.triangles.size(), false);
  NearTriangles near;
  near.build(m, gone);
  std::set<Index> found;
  near.for_each_near({-10, -10, -10}, {10, 10, 10}, [&](Index s) { found.insert(s); });
  EXPECT_EQ(found.size(), m.triangles.size());
}

TEST(NearTriangles, DriftPastACellOrManyRewiredTrianglesAskForARebuild) {
  TriangleMesh m = testing::icosphere(2);
  const std::vector<bool> gone(m.triangles.size(), false);
  NearTriangles near;
  near.build(m, gone);
  near.moved(0, m.vertices[0] + Vec3{10, 0, 0});
  EXPECT_TRUE(near.stale());
  near.build(m, gone);
  for (Index t = 0; t < m.triangles.size() / 8; ++t) near.rewired(t);
  EXPECT_TRUE(near.stale());
}

}  // namespace
}  // namespace cvtmesh
