// Two-sided Hausdorff distance between surfaces, Metro-style: area-uniform samples of each
// surface, spread evenly, plus its vertices and edge midpoints, each point's distance to the
// other surface by an AABB tree.
#pragma once

#include <cstdint>

#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

struct HausdorffSettings {
  // Area-uniform samples per surface, spread evenly (stratified), in addition to its vertices
  // and edge midpoints, which count for the max only. 0 = automatic:
  // max(200'000, 2 × triangles of the larger mesh), capped at 1'000'000.
  std::size_t samples = 0;
  std::uint64_t seed = 1;  // sampling is deterministic for a given seed, on any thread count
};

struct OneSidedDistance {
  double max = 0, mean = 0, rms = 0;  // absolute, in the meshes' units
};

struct HausdorffReport {
  OneSidedDistance a_to_b, b_to_a;
  double max = 0, mean = 0, rms = 0;  // two-sided: the larger of the two one-sided figures
  double reference_diagonal = 0;      // bounding-box diagonal of `b`, the reference
  std::size_t samples_per_surface = 0;
  double max_pct() const { return 100 * max / reference_diagonal; }
  double mean_pct() const { return 100 * mean / reference_diagonal; }
  double rms_pct() const { return 100 * rms / reference_diagonal; }
  // A one-sided figure in % of the diagonal: which side the two-sided figure comes from tells
  // chords cutting inside the reference (a to b) from detail the mesh misses (b to a).
  double pct(double distance) const { return 100 * distance / reference_diagonal; }
};

// The same distances for the meshes scaled by 2^exponent (see scaled_by_power_of_two).
HausdorffReport scaled_by_power_of_two(HausdorffReport report, int exponent);

// `b` is the reference (its diagonal normalises the percentages). Both meshes must be non-empty.
// Computed on both meshes scaled by the same power of two to about unit size, so any units work.
HausdorffReport hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                   const HausdorffSettings& settings = {});

}  // namespace cvtmesh

namespace cvtmesh {

// How closely output feature edges follow the input's feature curves: each input feature edge
// sampled at spacing at most 1/4000 of the bbox diagonal (and at its ends), each sample's
// distance to the nearest output feature edge. Max and mean (over samples) are absolute; both
// are +infinity when there are input features but no output feature edges, 0 when there are
// no input features. Computed at about unit size, like hausdorff_distance.
struct FeatureDistance {
  double max = 0, mean = 0;
};
FeatureDistance feature_distance(const TriangleMesh& input, const std::vector<Edge>& input_edges,
                                 const TriangleMesh& output, const std::vector<Edge>& output_edges);

// The input's corners found among the output's vertices at exactly their input position.
std::size_t corners_kept(const TriangleMesh& input, const Features& features,
                         const TriangleMesh& output);

}  // namespace cvtmesh
