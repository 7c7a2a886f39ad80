// Isotropic remeshing by CVT (paper §4): seeds are spread on the surface, moved to minimise the
// CVT energy over the exact RVD (L-BFGS, or Lloyd), first freely in 3D (restricted CVT), then
// constrained on the surface (constrained CVT); the output is their restricted Delaunay
// triangulation.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/mesh.hpp"
#include "cvtmesh/sizing.hpp"
#include "cvtmesh/topology.hpp"

namespace cvtmesh {

enum class Optimizer { lbfgs, lloyd };
enum class CvtMode { rcvt, ccvt, both };

// What a remesh is doing, for progress output. `phase`:
// - "rcvt", "ccvt", "ccvt-surface": an iteration of the CVT, with its energy and gradient norm;
// - "topology": a round of topology control (paper §4.4) that added seeds: `iteration` the
//   round, `seeds` the seeds after it, `defects` the triangles at defects that it seeded;
// - "redo": the output lost the input's topology, and the remesh starts again (issue 18):
//   `iteration` the try (2, 3, ...), `seeds` its vertex count, `detail` how it differs;
// - "sheets": a non-manifold input, remeshed whole, lost its topology or gained edges of three
//   or more triangles beside the input's: its sheets are remeshed apart (see sheets_apart).
// elapsed_seconds counts from the start of the current try.
struct RemeshProgress {
  const char* phase;
  int iteration;
  double energy, gradient_norm, elapsed_seconds;
  std::size_t seeds = 0, defects = 0;
  const char* detail = "";
};

struct RemeshSettings {
  // Output size: exactly one of these three must be set. With `sizing`, the vertex count scales
  // the target lengths to give that many vertices, and an edge length is their median over the
  // surface (by area); a sizing by edge_lengths or edge_length_at may also set none of the
  // three, and is then taken as it is.
  std::size_t vertices = 0;    // number of output vertices
  double edge_length = 0;      // target edge length, in the mesh's units
  double edge_length_rel = 0;  // target edge length, as a fraction of the bbox diagonal
  int iterations = 10;         // cap on the iterations of each phase (RCVT from spread seeds: half)
  double gradient_tolerance = 1e-3;  // stop a phase when ‖∇F‖ falls below this × its start
  Optimizer optimizer = Optimizer::lbfgs;
  // both: RCVT, then CCVT (paper §4.2); on an input without features and with ρ = 1 (no
  // adaptive or user sizes), RCVT alone, with CCVT's iterations too.
  CvtMode mode = CvtMode::both;
  std::uint64_t seed = 1;           // random initial seeds: same seed, same output
  std::vector<Vec3> initial_seeds;  // if not empty: used instead of spread ones
  // Called once per iteration, per round of topology control that adds seeds, and per redo.
  std::function<void(const RemeshProgress&)> progress;
  // Polled often (every few milliseconds of work), from any of the worker threads: when it
  // returns true, remesh stops and throws Cancelled. Must be thread-safe and cheap.
  std::function<bool()> cancel;
  // Seconds, 0 for none. Once they have passed, the optimization, polishing and topology
  // control stop where they are, and the output is extracted from the seeds as they are: a
  // valid mesh (the same guarantees), less optimized (RemeshResult::time_limit_reached). The
  // final extraction and the report run after the limit.
  double time_limit = 0;
  // Rounds of local Lloyd steps around the output's badly shaped triangles (smallest angle
  // under 35° or Q under 0.65), after the optimization; 0 turns this off.
  int polish_rounds = 3;
  // Sweeps of edge flips and vertex moves around the output's badly shaped triangles, the last
  // step (see RemeshResult::shape_flips); 0 turns it off.
  int shape_sweeps = 5;
  // Rounds of fitting the output to the input, last, after the vertices move onto their cells'
  // normal lines and those beside the input's untraced creases onto them (see
  // RemeshResult::vertices_on_cell_normals, vertices_snapped and vertices_fitted); 0 does none of
  // it and keeps every vertex on the input surface where the sweeps left it.
  int fit_rounds = 2;
  // Rounds of topology control (paper §4.4; see RemeshResult): each adds seeds where the
  // output misses feature links or is not homeomorphic to the input, and triangulates again.
  // The best output of all the rounds is kept; they stop early after 4 rounds in a row that
  // found nothing better. Where they end without the input's topology, up to three times as many
  // follow from the best round, refining every restricted cell that is not a disc, with the
  // seeds they add pinned (not polished). 0 turns the rounds off.
  int topology_rounds = 12;
  // Sharp features and boundaries kept by CCVT (paper §4.3): corners become fixed output
  // vertices, feature curves chains of output edges. Not applied with mode rcvt.
  FeatureSettings features;
  // Edge lengths that vary over the surface (issue 20); inactive: uniform.
  SizingSettings sizing;
  // The report's two-sided Hausdorff distance between output and input (RemeshResult::hausdorff),
  // measured with the AABB tree the remesher built anyway; unset: not measured.
  std::optional<HausdorffSettings> hausdorff;
};

// Achieved edge length over target edge length, over the output's edges (target: the mean of
// the targets at the edge's ends; uniform: the length that spreads the vertices evenly).
struct EdgeLengthRatio {
  double p5 = 0, median = 0, p95 = 0;
};

struct RemeshResult {
  // The restricted Delaunay triangulation of the final seeds; where a feature link is missing
  // and one edge flip makes it, flipped (links_flipped); a corner at a boundary tip that it
  // leaves without a triangle gets the one its two links bound (tips_closed).
  TriangleMesh mesh;
  int iterations = 0;       // over all phases
  int rvd_evaluations = 0;  // RVD computations (energy + gradient evaluations)
  // Of the input scaled by a power of two to about unit size (the remesher works on that
  // exact copy, so that any units give the same output up to the scale).
  double energy_initial = 0, energy_final = 0;
  double gradient_norm_initial = 0, gradient_norm_final = 0;
  // The AABB tree and the features, needed from CCVT on, are built while RCVT runs: their time
  // counts in seconds_rcvt. Extraction includes the polishing and the topology control.
  double seconds_initialization = 0, seconds_rcvt = 0, seconds_ccvt = 0, seconds_extraction = 0;
  // What topology control added (issue 18: at most 25% of a remesh at the corpus median): its
  // checks, rounds and last step (part of seconds_extraction), and a whole remesh redone
  // without sharp features when keeping them cost the topology (counted in every phase when
  // its output is taken, else in seconds_extraction).
  double seconds_topology = 0;
  // The report's Hausdorff distance (`hausdorff`), not part of the remesh's phases.
  double seconds_hausdorff = 0;
  std::vector<double> energies;           // energy after each accepted iteration, in order
  std::size_t defects_polished = 0;       // badly shaped triangles before polishing
  int polish_rounds = 0;                  // polishing rounds that moved seeds
  Features features;                      // of the input
  std::vector<Edge> feature_edges;        // output edges that trace the input's feature curves
  std::size_t feature_edges_missing = 0;  // links of the curves' seed chains the output lacks
  // Sharp edges of the input (kept for their dihedral angle alone, not boundaries, non-manifold
  // or user edges) left out because the output kept the input's topology, or passed through
  // itself where the input does not, only with them: validity wins (issue 18). Sorted; empty
  // when every crease was kept.
  std::vector<Edge> feature_edges_dropped;
  // Uniform sizes gave way (issue 18: validity first): the output of even edge lengths did not
  // keep the input's topology, and one remeshed again with adaptive sizes (SizingSettings's
  // local feature size, at the same count or at a grown one: see count_grown) was kept. False
  // when the sizes were the caller's.
  bool sizes_adapted = false;
  // Even sizes graded down towards feature gaps narrower than them (SizingSettings::
  // gap_gradation: a hole smaller than an edge, a slot, a thin strip): the shortest target
  // length there, as a fraction of the even length. 0 when the sizes stayed even (or were the
  // caller's).
  double gap_length_min = 0;
  // Vertices asked for on top of the count requested, where neither topology control nor
  // adaptive sizes kept the input's topology: the count doubled, at most twice, with even sizes
  // and, where those lost it again, adaptive ones at the same count (issue 18 item 2: the count
  // grows for the topology alone); or where the features (boundary loops, creases) needed
  // more seeds of their own than the count left (many small holes, with sizes graded down to
  // them): the count grew to twice their need. 0 when the count asked for sufficed.
  std::size_t count_grown = 0;
  // Where the input is non-manifold along edges of three or more triangles, and remeshed whole
  // it lost its topology there or gained such edges beside the junction: the sheets meeting
  // there, remeshed apart and zipped along the junction, when that output was the better. 0
  // when the input was remeshed whole.
  std::size_t sheets_apart = 0;
  // Topology control (paper §4.4), at most 3 × `topology_rounds` rounds, each triangulating and
  // polishing again: seeds that joined a feature curve, or came in on one, where the output had
  // cut it; and seeds added in the extra pieces of restricted cells split in several, or in
  // pieces that are not discs (where the output was not homeomorphic to the input). Counted up
  // to the round whose output is kept: the best of all, by topology first (the input's, then
  // fewest non-manifold edges and vertices), then corners kept, then links missing, then Qmin.
  std::size_t links_mended = 0;
  std::size_t islands_seeded = 0;
  // Seeds added where the triangulation failed the topological ball property (a non-manifold
  // edge or vertex, a boundary edge the input lacks, a fold): at the points where the defective
  // triangles' dual Voronoi edges cross the surface (Delaunay refinement).
  std::size_t seeds_refined = 0;
  // The output vertices of the seeds that topology control added (ids into `mesh`, sorted):
  // where the surface needed more vertices than the requested count for its topology.
  std::vector<Index> vertices_added;
  std::size_t links_flipped = 0;  // links still missing after that, made by one edge flip
  std::size_t tips_closed = 0;    // triangles added at corners of boundary tips
  int mend_rounds = 0;
  // The last step: triangles removed at the defects the rounds could not mend (non-manifold
  // edges and vertices, folds), so that the output is always an oriented manifold. Each leaves
  // a hole. Where closing all these holes (on their own vertices, or by a fan around a new one
  // where that would repeat an edge) gives back the input's topology and a manifold, they are
  // closed (local re-triangulation: an input that crosses itself defeats refinement there);
  // otherwise, when this is not 0, the output's topology differs from the input's.
  std::size_t triangles_removed = 0;
  std::size_t holes_closed = 0, triangles_closing_holes = 0;
  std::size_t vertices_closing_holes = 0;  // centres of holes closed by a fan
  // Input triangles that pass through another of their component, found where an output lacked
  // the input's topology or passed through itself (0 when none, or when no output did either):
  // sheets that cross share their cells at any spacing, so the topology there cannot be the
  // input's, and the rounds stop refining there.
  std::size_t input_crossing_triangles = 0;
  // Output triangles that pass through another where the input does not pass through itself
  // (issue 18: a valid output): topology control refines where its extractions cross
  // themselves, and where the finishing steps made crossings, they are run again with each change
  // around them checked for crossings (`vertices_guarded`: how many vertices that guarded); where
  // some are left, the long edges there are halved, their middles on their own side of the
  // input (finish/split_crossings; `vertices_splitting_crossings`: the vertices that added, the
  // count given way to validity). Not 0 only where none of that removed them all.
  std::size_t output_crossing_triangles = 0;
  std::size_t vertices_guarded = 0;
  std::size_t vertices_splitting_crossings = 0;
  // Flat or folded ears removed at the boundary (finish/flat_ears): triangles whose two edges at
  // one vertex, not a corner, were boundary edges meeting at 160° or more (120° at a vertex that
  // is no seed: a cell's far piece), or that folded back more than 120° over their neighbour
  // across the third edge. The boundary loop stays;
  // the vertex goes, and the links from it to its two neighbours count as missing.
  std::size_t flat_ears_removed = 0;
  // Flat pairs merged at the boundary (finish/flat_pairs): a vertex that is no corner, on a
  // boundary of 160° or more, with two triangles, which became one without it; kept only where
  // the output, swept and through the halving rounds, is better shaped so than without. The
  // boundary loop stays.
  std::size_t flat_pairs_merged = 0;
  // Surface vertices of three triangles removed for the triangle of their three neighbours,
  // where that is better shaped (finish/valence_three): how topology control's seeds next to
  // others often end. The topology stays; so may the count of vertices asked for not.
  std::size_t valence_three_removed = 0;
  // Triangles over 100° at a boundary vertex (a boundary corner, whose angle no flip or move
  // changes), or at any vertex in a triangle the shape sweeps left under the bar's Q 0.6, halved
  // across from it (finish/split_obtuse_corners), where the shape sweeps then left the output
  // better than without: a vertex added each.
  std::size_t obtuse_corners_split = 0;
  // The output's last touch, after all the above: edges flipped between nearly coplanar
  // triangles and vertices moved along the surface, around badly shaped triangles, each only
  // where the worst triangle it touches gets better. Neither changes the topology; feature,
  // corner and boundary vertices do not move, feature edges do not flip.
  std::size_t shape_flips = 0, shape_moves = 0;
  // ... and, where neither helps, short edges of badly shaped triangles collapsed: a surface
  // vertex, or a curve vertex along its curve, merged into its neighbour (V - 1, E - 3, F - 2:
  // the topology stays); at most 1% of the vertices. Counted with them, and past that cap: edges
  // of no length (both ends at one point, where a folded input lies on itself) collapsed last of
  // all, so that no triangle of no area is left.
  std::size_t short_edges_collapsed = 0;
  // Surface vertices moved, before the sweeps, from one sheet of the input onto the sheet their
  // triangles face (finish/own_sheet): beside a sharp edge whose faces meet at a narrow angle, a
  // seed on one face whose cell reached round the edge served triangles along the other, cutting
  // through the part.
  std::size_t vertices_onto_own_sheet = 0;
  // Surface vertices moved onto an input crease that the output does not trace as a feature,
  // before the fit (finish/snap_to_creases): a low-poly input remeshed finer keeps its edges.
  std::size_t vertices_snapped = 0;
  // Surface vertices moved, before those, from the seed to the point where the seed's cell's
  // mean normal line through its centroid meets the input (finish/cell_normal_points): at a tip
  // or a ridge narrower than an edge, the nearest point to the centroid lies on a flank.
  std::size_t vertices_on_cell_normals = 0;
  // Surface vertices moved off the input along their normals, last of all, so that the input lies
  // between them and their triangles' middles (finish/fit_surface): the chords of a curved
  // surface all fall inside convex parts otherwise. Never where θmin or Qmin would fall.
  std::size_t vertices_fitted = 0;
  TopologyReport input_topology;  // of the input, as analyze_topology gives it
  EdgeLengthRatio edge_length_ratio;
  bool time_limit_reached = false;  // RemeshSettings::time_limit stopped the work early
  // Output (a) against input (b), when RemeshSettings::hausdorff asks for it.
  std::optional<HausdorffReport> hausdorff;
};

// The number of vertices the settings ask for: `vertices`, or the count whose equilateral
// triangles of the given edge length cover the surface's area (with a sizing, of the target
// lengths, which this computes: for adaptive sizing, the local feature size). Throws
// InvalidArgument when not exactly one size is set, or it is out of range (fewer than 4 vertices,
// more than 50 million).
std::size_t requested_vertex_count(const TriangleMesh& mesh, const RemeshSettings& settings);

// The edge length of that many vertices spread evenly over the surface, as equilateral
// triangles: the scale of the output (with a sizing, of its median edge). Throws as
// requested_vertex_count.
double requested_edge_length(const TriangleMesh& mesh, const RemeshSettings& settings);

// Each connected component (triangles joined by edges) is remeshed on its own, with its own seeds
// (none owns another component's surface): the count is shared by area (under a sizing, by what
// the sizing of the whole asks of each), each component getting at least 4 vertices and more than
// its feature seeds. Components that touch at a vertex keep it as a corner and still touch there
// in the output. With initial seeds the mesh is remeshed whole.
// Throws InvalidArgument for bad settings, InputError for a mesh without area, ResourceError
// when the job would need more memory than is available (checked first), Cancelled when
// settings.cancel asked to stop.
RemeshResult remesh(const TriangleMesh& mesh, const RemeshSettings& settings);

}  // namespace cvtmesh
