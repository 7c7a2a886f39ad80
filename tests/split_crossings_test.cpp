// Crossings left after the finishing steps: the long edges there halved, their middles on their
// own side of the input (finish/split_crossings).
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

#include "cvtmesh/topology.hpp"
#include "finish/split_crossings.hpp"
#include "geometry/self_crossings.hpp"
#include "geometry/surface_projector.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using testing::concatenate;
using testing::icosphere;

// `mesh` with every triangle turned over: an inner wall's faces look inwards.
TriangleMesh turned_over(TriangleMesh mesh) {
  for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

// A hollow ball: the unit sphere and, facing inwards, a sphere of radius 0.95 inside it. An
// embedded surface whose wall is 0.05 thick.
TriangleMesh hollow_ball(int levels) {
  return concatenate(icosphere(levels), turned_over(icosphere(levels, 0.95)));
}

// A remesh of the hollow ball whose outer sphere is far coarser than the wall is thick: an
// icosahedron split once, whose faces come within 0.93 of the centre, through the inner sphere.
RemeshResult coarse_outside() {
  RemeshResult result;
  result.mesh = concatenate(icosphere(1), turned_over(icosphere(3, 0.95)));
  return result;
}

TEST(SplitCrossings, ChordsThroughAThinWallAreHalvedOntoTheirOwnSideUntilNoneCrosses) {
  const TriangleMesh input = hollow_ball(5);
  const SurfaceProjector surface(input);
  InputCrossings input_crossings(input);
  RemeshResult result = coarse_outside();
  const TopologyReport topology_before = analyze_topology(result.mesh);
  const std::size_t vertices_before = result.mesh.vertices.size();
  const std::size_t crossing_before = crossings_of_its_own(result.mesh, input_crossings).size();
  ASSERT_GT(crossing_before, 0u);
  result.output_crossing_triangles = crossing_before;

  const std::size_t added = split_crossings(result, surface, input_crossings, 8);
  EXPECT_GT(added, 0u);
  EXPECT_EQ(result.mesh.vertices.size(), vertices_before + added);
  EXPECT_EQ(result.output_crossing_triangles, 0u);
  EXPECT_TRUE(crossings_of_its_own(result.mesh, input_crossings).empty());
  // The same surface: two spheres, each closed and oriented, none of the triangles folded.
  EXPECT_TRUE(keeps_topology(analyze_topology(result.mesh), topology_before));
  // Each new vertex stands on the sheet of the edge it halved, not on the other side of the wall
  // (nearer to the edge's middle): a neighbour of it, an end of that edge, on the same sphere.
  for (std::size_t v = vertices_before; v < result.mesh.vertices.size(); ++v) {
    const double r = norm(result.mesh.vertices[v]);
    EXPECT_TRUE(std::abs(r - 1) < 1e-3 || std::abs(r - 0.95) < 1e-3) << "vertex " << v;
    bool beside = false;
    for (const Triangle& t : result.mesh.triangles)
      if (std::find(t.begin(), t.end(), v) != t.end())
        for (const Index w : t)
          beside |= w != v && std::abs(norm(result.mesh.vertices[w]) - r) < 1e-3;
    EXPECT_TRUE(beside) << "vertex " << v << " at radius " << r;
  }
}

TEST(SplitCrossings, AnOutputThatDoesNotCrossItselfIsLeftAsItWas) {
  const TriangleMesh input = hollow_ball(4);
  const SurfaceProjector surface(input);
  InputCrossings input_crossings(input);
  RemeshResult result;
  result.mesh = hollow_ball(3);
  const TriangleMesh before = result.mesh;
  EXPECT_EQ(split_crossings(result, surface, input_crossings, 8), 0u);
  EXPECT_EQ(result.mesh.vertices, before.vertices);
  EXPECT_EQ(result.mesh.triangles, before.triangles);
}

}  // namespace
}  // namespace cvtmesh
