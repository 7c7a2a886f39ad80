// Where the input surface passes through itself: pairs of triangles that intersect other than
// at the vertices and edges they share. There, every seed near the crossing owns a piece of the
// other sheet at any spacing, so no refinement gives the restricted Delaunay triangulation the
// surface's topology (README: topology control, the last step).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "geometry/surface_projector.hpp"

namespace cvtmesh {

// Whether triangles `a` and `b` of `mesh` intersect other than at the vertices they share (exact
// predicates): none shared, by the triangle test; one, whether the edge of either opposite it
// meets the other; two or three (an edge, a duplicate), never.
bool triangles_cross(const TriangleMesh& mesh, const Triangle& a, const Triangle& b);

// Per triangle of `mesh`, whether it crosses another (exact predicates). Triangles that share an
// edge are not tested: their overlap would be a fold, not a crossing.
std::vector<bool> self_crossing_triangles(const TriangleMesh& mesh);

// Crossing triangles (on `points`) as a surface to measure distances to, or null where there are
// none.
std::unique_ptr<SurfaceProjector> crossing_surface(const std::vector<Vec3>& points,
                                                   std::vector<Triangle> crossing);

// Where an input's triangles cross one another, searched on first need: most runs never need it
// (searched for every run, it added about 0.3 s to igea.ply's 2.2 s at 10k).
class InputCrossings {
 public:
  explicit InputCrossings(const TriangleMesh& surface) : surface_(surface) {}
  // The crossing triangles as a surface (crossing_surface), searched on the first call; null
  // where there are none.
  const SurfaceProjector* get();
  // Whether get() has searched; whether the search found any; how many triangles cross another
  // (0 before a search).
  bool searched() const { return searched_; }
  bool found() const { return found_ != nullptr; }
  std::size_t count() const { return count_; }

 private:
  const TriangleMesh& surface_;
  bool searched_ = false;
  std::size_t count_ = 0;
  std::unique_ptr<SurfaceProjector> found_;
};

// Whether the triangle of `points` `t` is at a crossing of the input's sheets (`crossings`:
// InputCrossings::get): one reaches the ball around its centroid whose radius is its longest edge.
bool at_crossing(const SurfaceProjector& crossings, const std::vector<Vec3>& points,
                 const Triangle& t);

// The triangles of an output that cross another where the input does not cross itself: a remesh
// of a surface that is embedded must be embedded too, but where the input passes through itself
// its output does as well. A triangle is at the input's crossings as at_crossing says, with the
// ball's radius the longest edge of the triangles at its vertices: a small triangle beside large
// ones strays from the surface as far as they do. The input is searched only if the output
// crosses itself somewhere.
std::vector<Triangle> crossings_of_its_own(const TriangleMesh& output, InputCrossings& input);

}  // namespace cvtmesh
