// The poles of a sample of a surface (Amenta-Bern): for each sample point, the farthest vertex of
// its Voronoi cell on each side of the surface. Together they approximate the medial axis, and a
// point's distance to the nearest pole approximates its local feature size (paper §4.1).
#pragma once

#include <vector>

#include "cvtmesh/vec3.hpp"

namespace cvtmesh {

struct SurfaceSample {
  Vec3 point;
  Vec3 normal;  // unit normal of the surface there (either orientation)
};

// The poles of the samples' 3D Delaunay triangulation (CGAL), each sample's farthest Voronoi
// vertex along +normal and along -normal. A sample on the convex hull has an unbounded cell: its
// pole on the outer side is at infinity, and none is given there.
std::vector<Vec3> sample_poles(const std::vector<SurfaceSample>& samples);

}  // namespace cvtmesh
