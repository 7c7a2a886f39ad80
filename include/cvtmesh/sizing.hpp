// Sizing of adaptive remeshing (paper §4.1): the local feature size of a surface, estimated from
// the poles of a dense sample (Amenta-Bern) and rays along the normals, and graded so that
// neighbouring sizes differ smoothly.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

struct LfsSettings {
  // The sample is the mesh's vertices, which lie on the surface the mesh approximates. Area
  // samples on its flat triangles would see the polyhedron itself, whose medial axis reaches
  // every edge: sizes would fall towards 0 at each edge of a tessellated sphere. These many
  // are added nonetheless, for a mesh whose vertices are too sparse for its parts (a coarse
  // CAD model, whose edges are true features). The poles see parts thinner than the sample's
  // spacing thicker than they are; the rays along the normals bound them (below).
  std::size_t samples = 0;
  std::uint64_t seed = 1;  // the sampling: same seed, same sizes
  // The sizes are made (1/gradation)-Lipschitz along the mesh's edges: the largest such
  // function under the raw estimate. Higher: smoother size changes (and smaller sizes near
  // thin parts' surroundings). 0: no grading, the raw estimate.
  double gradation = 1.5;
  // The mesh's sharp features and boundaries (detect_features), or null: near them, the size
  // falls to the gap to another part of them (capped_by_feature_gaps) before the grading.
  const Features* features = nullptr;
};

// The local feature size at each vertex of `mesh` (the distance to the medial axis, estimated as
// the distance to the nearest pole of the samples, and at most half the distance to the surface
// along the vertex's normal either way: the largest ball touching the surface there is centred
// on the normal), in the mesh's units; 0 for a vertex used by no triangle. Throws
// InvalidArgument for a mesh without area or a negative gradation.
std::vector<double> local_feature_size(const TriangleMesh& mesh, const LfsSettings& settings = {});

// Which wedges between feature curves (sectors of the surface under 60° at a vertex) narrow the
// sizes near their tips in capped_by_feature_gaps.
enum class WedgeGaps {
  all,  // every one: the local feature size (issue 20 item 1)
  // Only narrow ones (under 30°, issue 18 item 6's narrow input angles) whose two sides are
  // curves that end at the tip (a corner) and run for at least 4 times the size there. Near the
  // tip of a traced narrow wedge, even sizes leave a triangle with the short chord across it next
  // to one of the even length: a sliver (fandisk.off at 10k: θmin 22.9° away from its 19.4° tip;
  // 39.2° graded). The other wedges are no gap: a wider one gets well shaped even triangles, and
  // a side shorter than a couple of edges, or a curve folding back where no corner is, is not
  // traced (lion.off's 8° tip between a long crease and one an edge long: sizes graded down to it
  // only crowd small triangles there).
  traced_narrow,
};

// `sizes` (per vertex of `mesh`), each curve vertex's lowered to the narrowest gap across which
// another part of the feature curves faces it (issue 20 item 1): the distance to the nearest
// point of them whose chord makes at least 60° with both curves there, where the gap goes on (a
// gap further along the curve, it faces them within twice the gap). A strip between two creases
// or boundaries gets its width, a closed curve its own width, the sides of a wedge under 60°
// their distance (as `wedges` says; the others are no gap near their tips, about as far from it
// as each other); two curves meeting at a wider angle never narrow each other, nor do curves
// that pass each other at one spot only. Only gaps under a vertex's size are looked for: the
// size bounds the search. Each boundary loop shorter than 2π times a vertex's size also caps
// that vertex at the loop's length over 2π, about six edges around a small hole (no two sides
// of a triangular one face each other).
std::vector<double> capped_by_feature_gaps(const TriangleMesh& mesh, const Features& features,
                                           std::vector<double> sizes,
                                           WedgeGaps wedges = WedgeGaps::all);

// Target edge lengths for remeshing (RemeshSettings::sizing): one of three sources, then one
// scale factor for the output size, then the grading (adaptive only), then the clamps. The
// lengths are linear over each input triangle. CVT gives cells of about equal energy, so a
// density ρ spreads seeds ∝ √ρ by area (paper §4.1, [DFG99]): the remesher uses ρ = h⁻⁴ for
// edges about h long.
struct SizingSettings {
  // > 0: the paper's density ρ = 1/lfs² (§4.1), edges h ∝ √lfs: thin parts and tight curvature
  // get short edges, and the chord error h²/(8 lfs) is about even where lfs is the radius of
  // curvature. The lengths, once scaled to the output size, are graded to change by at most
  // 1/adaptive per unit length (1.5 is a good default; higher: smoother). h ∝ lfs, Theorem 2's
  // ε-sampling, was tried: it took more seeds from topology control on the corpus at 2k (3,853
  // against 1,796 at seed 1), with a worse Hausdorff max and θmin. h is capped at 1.6 lfs instead
  // (four edges round a thin part's section) where, with a vertex count, that takes at most a
  // tenth of it, else at 2 lfs (π edges) where that takes at most two fifths; a handle thinner
  // than the clamp below gets six edges round its throat, as a hole does, while a cap holds.
  double adaptive = 0;
  std::size_t lfs_samples = 0;  // LfsSettings::samples, for adaptive
  // Adaptive only: the local feature sizes are kept within this factor of their median (by
  // area) either way, the lengths within its square root.
  // The raw estimate falls towards 0 where parts touch, at creases and on noise: unclamped,
  // a few such spots would take a large share of the vertices and cells far smaller than
  // their neighbours (diplodocus at 2k: θmin 2.9°, topology lost; clamped at 10: see README).
  // A hole far smaller than the clamp allows narrows the lengths further, to about six edges
  // around it, as an even sizing's holes do.
  double adaptive_range = 10;
  // Or a target length per input vertex, in the mesh's units (> 0 and finite on the vertices the
  // triangles use).
  std::vector<double> edge_lengths;
  // Or a function of position (mesh units), called once per input vertex.
  std::function<double(const Vec3&)> edge_length_at;
  // Clamps on the lengths, in the mesh's units, applied after the scaling; 0: none.
  double min_edge_length = 0, max_edge_length = 0;
  // With none of the three sources above (an even sizing): > 0 grades the lengths down to the
  // gaps under half of them across which feature curves face each other (capped_by_feature_gaps,
  // wedges left out: a hole far smaller than an edge, a slot, a thin strip) and to handles as
  // thin (a tunnel whose loop round is under π half-lengths: its loop over π), changing by at
  // most 1/gap_gradation per unit length; elsewhere they stay even. Small features force small
  // triangles, as in quality meshers (Shewchuk's Triangle): the hole's short edges next to edges
  // of the even length make slivers (ChineseDragon-10kv.off, two holes 0.1-0.3% of an edge across:
  // θmin 0.2-4.4° at 1k-10k). Gentler than adaptive's 1.5: steeper grading cost 5-15° of θmin
  // around the holes. With a vertex count, made gentler still (to 1 at least) where the grading
  // would take over a tenth of the vertices from the rest of the surface. 0: even lengths
  // everywhere.
  double gap_gradation = 5;

  bool active() const { return adaptive > 0 || !edge_lengths.empty() || edge_length_at; }
};

}  // namespace cvtmesh
