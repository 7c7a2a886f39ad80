// Topology control of the output (paper §4.4), after the optimization: the restricted Delaunay
// triangulation must trace every feature curve and be homeomorphic to the input. Where it is
// not, seeds are moved or added there, and the output is made again.
#pragma once

#include <chrono>
#include <functional>
#include <vector>

#include "cvt/polish_defects.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/topology.hpp"

namespace cvtmesh {

class InputCrossings;

struct MendContext {
  const TriangleMesh& surface;
  const TopologyReport& surface_topology;
  const Features& features;
  const CurveProjector& curves;
  const SurfaceProjector& projector;
  const CvtObjective& placement;  // where seeds may go (see extract_polished)
  const CurveSpacing& spacing;    // target edge lengths along the curves
  PolishSettings polish;
  ExtractionMemory& extraction;  // what the last extraction of `surface` left (extract_polished)
  // Told of each round that adds seeds (RemeshSettings::progress; null: nobody), with the time
  // since `start`.
  const std::function<void(const RemeshProgress&)>* progress = nullptr;
  std::chrono::steady_clock::time_point start{};
};

struct MendReport {
  std::size_t links_mended = 0;   // seeds that joined a curve, or came in on one
  std::size_t islands = 0;        // seeds added in extra pieces of cells, and pieces not discs
  std::size_t refined = 0;        // seeds added where defects' Voronoi edges cross the surface
  std::size_t links_flipped = 0;  // links still missing after the rounds, made by an edge flip
  std::size_t tips_closed = 0;    // triangles added at boundary tips (close_corner_wedges)
  int rounds = 0;                 // rounds that changed the seeds
  int polish_rounds = 0;          // polishing rounds over all the extractions after the first
};

// Whether a surface of `triangles` triangles, `crossing` of which cross another, passes through
// itself so widely that no count or sizing of the seeds gives the output its topology: a twentieth
// of its triangles or more (a part thinner than the noise on it, folded through itself: blade.off
// with its vertices moved by 5% of an edge, 28% of its triangles, took over 300 s at 9k, most of
// it in rounds and retries that never kept the topology). Then the rounds are not pinned and the
// remesh is not tried again (remesh/topology_first). The shared meshes that cross themselves do
// so at 2.2% of their triangles at most (man.off), and keep their topology.
bool crosses_itself_widely(std::size_t crossing, std::size_t triangles);

// Up to `rounds` times, while the output misses links of the feature chains, or its topology
// differs from the surface's (non-manifold, or other components, Euler characteristic or
// boundary loops), or its triangles cross one another where the input's do not: mends the links no
// single well-shaped edge flip makes (mend_missing_links), puts a new surface seed in each extra
// piece of a cell near the defects (cell_islands, defect_seeds), refines at the crossing triangles,
// and extracts again (polishing around the new seeds). Each extraction is finished as it would be
// returned: the missing links flipped in where one edge flip makes them (flip_in_links; with no
// angle under 30°, or, for links the seeds do not mend, 15°), and corners left without a triangle
// at a boundary tip given theirs (close_corner_wedges). Returns the best of these outputs, by the
// input's topology, then fewest non-manifold edges and vertices, then fewest crossing
// triangles, then most corners, then fewest
// links missing, then best Qmin (the latest of equals); seeds, constraints and report are as of
// that round. Where the rounds end without the input's topology, up to 3 × `rounds` more start
// from the best round: they also refine every cell piece that is not a disc and every split
// cell, wherever it is, and polishing no longer moves the seeds they add; not where the input
// crosses itself widely (crosses_itself_widely). No split cell is seeded where the input crosses
// itself (`crossings`: where the context's surface does, searched once needed, and kept for the
// finishing steps' check, finish/crossing_guard).
// Independent of the thread count.
PolishedOutput mend_topology(const MendContext& context, InputCrossings& crossings,
                             PolishedOutput output, std::vector<Vec3>& seeds,
                             SeedConstraints& constraints, int rounds, MendReport& report);

}  // namespace cvtmesh
