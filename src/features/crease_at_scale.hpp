// Whether a curve of sharp edges is still a crease at the output's resolution (issue 18: defaults
// that never hurt). A dihedral angle measured between two input triangles says nothing about the
// scale of the output: on a coarse organic model or a noisy scan, many edges fold by more than the
// feature angle, but the surface around them bends as much within one output edge length, and
// tracing them pins seeds to jagged curves that cost angles and topology. A crease of a CAD part
// has flat (or gently curved) sides at that scale, and at the input's own resolution too: a
// low-poly animal remeshed finer than its polygons has flat sides at the output's scale, yet its
// folds are only the coarsest of a surface whose every edge bends.
#pragma once

#include <vector>

#include "cvtmesh/features.hpp"
#include "features/edge_uses.hpp"

namespace cvtmesh {

class CreaseScale {
 public:
  // `uses`: the mesh's edge_uses (kept by reference). `barrier`: sorted feature edges that the
  // sides of a crease do not extend across.
  CreaseScale(const TriangleMesh& mesh, const std::vector<EdgeUse>& uses,
              const std::vector<Edge>& barrier);

  // For an edge of exactly two triangles, the surface within `radius` of its midpoint on each
  // side (reached across non-barrier edges): the angle between the two sides' area-weighted
  // normals (the fold seen at that scale), and the sides' roughness, the larger of their
  // area-weighted mean angles between a triangle's normal and its side's normal. Degrees. And
  // the narrower side's width: how far its triangles' corners reach from the edge's line, or
  // less where a boundary comes nearer.
  struct Measure {
    double fold_deg = 0;
    double roughness_deg = 0;
    double width = 0;
  };
  Measure measure(const Edge& edge, double radius) const;

  // A curve (its input vertex ids, closed or not) is a crease at `scale` when at least half of
  // its measured edges (up to 9, spread along it) fold by at least `angle_deg` at that scale
  // with sides no rougher than a sixth of it (10° at the default 60°), and no narrower than
  // 0.3 `scale` (a strip between two creases, such as a narrow chamfer or step, whose triangles,
  // with seeds `scale` apart on both its curves, would have angles under atan(0.6) = 31°).
  bool is_crease(const FeatureCurve& curve, double scale, double angle_deg) const;

  // Of the same measured edges of a curve, how many have an input around them that bends by a
  // tenth of `angle_deg` at most (6° at 60°): the median dihedral angle of the non-barrier edges
  // of the triangles at their two ends. On the 57 meshes of ../shared/data and its corpus, that
  // median is under 3° along most of the creases of CAD parts and polyhedra, and 7° to 28° along
  // most of the folds of low-poly and scanned organic models (hand, pig, cow, femur, bones).
  struct Votes {
    std::size_t smooth = 0;
    std::size_t measured = 0;
  };
  Votes smooth_around(const FeatureCurve& curve, double angle_deg) const;

 private:
  struct Side {
    Vec3 normal_sum;  // area-weighted: the sum of the triangles' unnormalized normals
    double roughness_deg;
  };
  Side side(std::size_t first, bool flip, const Vec3& centre, double radius) const;
  // How far from the line through a and b the surface on first's side reaches, within `radius`
  // of their midpoint (the side ends at the barrier: another crease), or how near a boundary
  // edge of the side comes to the midpoint, whichever is less.
  double side_width(std::size_t first, const Vec3& a, const Vec3& b, double radius) const;
  // The triangle across t's edge k = (t[k], t[k+1]), or none for an edge of other than two
  // triangles or on the barrier.
  std::size_t across(std::size_t t, int k) const { return across_[3 * t + k]; }
  // The angle between the normals of t and the triangle across its edge k (there must be one).
  double dihedral_deg(std::size_t t, int k) const;
  double input_bend_deg(const Edge& edge) const;

  const TriangleMesh& mesh_;
  const std::vector<EdgeUse>& uses_;
  std::vector<std::size_t> across_;
  std::vector<char> on_boundary_;  // per corner 3 t + k: edge k of t is a boundary edge
  std::vector<std::size_t> around_start_, around_;  // per vertex, its triangles (compressed)
};

}  // namespace cvtmesh
