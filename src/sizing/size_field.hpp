// The target edge lengths of a remesh (issue 20), on the remesher's copy of the input: one per
// vertex, linear over each triangle, scaled to the requested output size and clamped.
#pragma once

#include <optional>
#include <vector>

#include "cvtmesh/remesh.hpp"

namespace cvtmesh {

class SizeField {
 public:
  // `sizes`: per vertex of `mesh`, > 0 on the vertices its triangles use (others are ignored).
  SizeField(const TriangleMesh& mesh, std::vector<double> sizes);

  double at_vertex(Index v) const { return sizes_[v]; }
  // At point p of triangle t, interpolated linearly.
  double at(std::size_t t, const Vec3& p) const;
  // The vertex count whose seeds these sizes ask for: Σ over triangles of area × the mean of
  // 1 / (√3/2 h²) at its corners (equilateral triangles of side h, two per vertex).
  double vertex_count() const;
  // The CVT density per vertex, (reference / h)⁴ (see SizingSettings).
  std::vector<double> density(double reference) const;
  // Per triangle, how likely an initial seed lands on it: area × mean h⁻² (seeds ∝ √ρ, §4.1).
  std::vector<double> seed_weights() const;
  // Along a curve through the mesh's vertices: its ∫ ds / h, segment by segment (one entry per
  // vertex, the first 0).
  std::vector<double> steps_along(const std::vector<Index>& polyline) const;

 private:
  const TriangleMesh* mesh_;
  std::vector<double> sizes_;
};

// The size field the settings ask for on `mesh` (the remesher's copy: spatially sorted by
// `new_id`, the caller's vertex v being mesh's new_id[v], or in the caller's order where new_id
// is empty; scaled to about unit size, with the settings scaled alike), scaled so that the
// output size comes out as `settings` asks (see RemeshSettings); unset when the sizing is not
// active and no feature gap or handle narrows the even lengths (SizingSettings::gap_gradation).
// An adaptive or even sizing given `features` (ids of `mesh`) narrows to their gaps
// (capped_by_feature_gaps), and either narrows to handles thinner than the gaps it looks for
// (handle_widths; an adaptive one, as to holes, under its clamp only). Even lengths graded down
// to handles that would take more than a tenth of the count at the steepest gradation leave the
// handles out, to topology control. Given `split_mesh`, where an even sizing's lengths change too
// fast along an edge at the gaps, the field is made on a split copy of `mesh` (split_for_sizes) put
// there, and `features` are moved onto it. Adaptive sizes are not split: their lengths stay
// within a range, and on the corpus at 2k splitting where they change twofold along an edge met
// the quality bar on 49 meshes against 52, with 992 seeds added against 737. Throws InvalidArgument
// for bad sizes or clamps, and for an adaptive sizing without an output size.
std::optional<SizeField> make_size_field(const TriangleMesh& mesh, const std::vector<Index>& new_id,
                                         const RemeshSettings& settings,
                                         Features* features = nullptr,
                                         std::optional<TriangleMesh>* split_mesh = nullptr);

}  // namespace cvtmesh
