// The restricted Voronoi diagram (RVD) of seeds on a triangle surface, computed exactly
// (paper §3): every input triangle is clipped by the Voronoi cells that meet it, found by
// propagation from the cell of one of its corners. Combinatorial decisions use exact
// predicates on the vertices' symbolic definitions, with a symbolic perturbation so that no
// decision is ever a tie. Works on a triangle soup: no connectivity is needed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// A vertex of a clipped polygon. Besides the input facet's plane it lies on two planes, its
// symbols: a value s >= 0 is the bisector of the cell's seed and seed s; a value < 0 is the input
// triangle's edge -(s+1), edge e joining corners e and (e+1)%3. Type A (an input corner) has two
// edges, type B (an input edge ∩ a bisector) one of each, type C (two bisectors) two bisectors.
struct RvdVertex {
  Vec3 point;    // rounded position
  double error;  // |exact − point| ≤ error in each coordinate (0 for input corners)
  std::array<std::int32_t, 2> symbols;

  int bisector_count() const { return (symbols[0] >= 0) + (symbols[1] >= 0); }
};

// The part of input triangle `triangle` inside the Voronoi cell of `seed`: a convex polygon,
// vertices in the input triangle's orientation.
struct RvdPolygon {
  Index seed;
  Index triangle;
  std::span<const RvdVertex> vertices;
};

// Receives the polygons of one traversal. Triangles are split into chunks of consecutive
// triangles; chunks run in parallel, each chunk's polygons arrive in order (triangle, then seed
// discovery order) on one thread. Reducing per chunk, then over chunks in order, makes results
// independent of the thread count.
class PolygonSink {
 public:
  virtual ~PolygonSink() = default;
  virtual void begin(std::size_t chunks) = 0;
  virtual void polygon(std::size_t chunk, const RvdPolygon& polygon) = 0;
  // A chunk's polygons have all arrived (called on the thread that gave them): a sink can size
  // the chunk's arrays exactly, or reduce it once the chunks before it are done, where holding
  // every chunk until end() takes memory in proportion to the polygons (igea.ply at 10k seeds:
  // 30 MB of CVT integrals). Threads take runs of consecutive chunks, each in order; handing them
  // out one by one in order instead kept fewer waiting, but two threads on neighbouring chunks made
  // remeshes 5% slower on two cores.
  virtual void chunk_done(std::size_t /*chunk*/) {}
  virtual void end() {}

  // Keeping chunks (issue 18: topology control and polishing work locally). A sink that serves
  // one traversal after another with the same TraversalMemory, where a few seeds change between
  // them, can keep what it holds of the chunks whose polygons have not changed, instead of
  // having those polygons handed over again. Such a sink returns true here. A traversal with a
  // memory whose polygons this sink took (it served the traversal that left them there, or one
  // since that changed no chunk) then calls begin_kept in place of begin: chunk c is as the sink
  // last had it where kept[c] is nonzero, and gets no polygons and no chunk_done. Otherwise (a
  // first traversal, another memory, no memory) the sink gets begin and every polygon, as any
  // sink.
  virtual bool keeps_chunks() const { return false; }
  virtual void begin_kept(std::size_t chunks, const std::vector<char>& /*kept*/) { begin(chunks); }

 protected:
  // For a sink whose chunks no longer stand for its polygons (it changed what it makes of them):
  // the next traversal hands it every polygon.
  void forget_kept_chunks() { served_ = 0; }

 private:
  friend class RestrictedVoronoiDiagram;
  std::uint64_t served_ = 0;  // the version of the memory's record this sink last served
};

struct TraversalStats {
  std::size_t polygons = 0;
  std::size_t cells_clipped = 0;    // (cell, triangle) clippings, polygons and empty ones alike
  std::size_t predicates = 0;       // side-of-bisector decisions
  std::size_t exact_fallbacks = 0;  // decisions the floating-point filter left to exact arithmetic
  std::size_t perturbed_ties = 0;   // exact ties decided by the symbolic perturbation
  std::size_t radius_searches = 0;  // kd-tree searches where a cell's stored nearest seeds did
                                    // not reach far enough (one per cell and wider reach)
  std::size_t triangles_replayed = 0;  // triangles whose polygons came from a TraversalMemory
};

struct RvdBuildTimes {
  double kdtree_seconds = 0, neighbors_seconds = 0;
  bool neighbors_reused = false;  // the lists came from a NeighborCache, not a search
};

// The seeds' lists of nearest seeds, carried from one diagram to the next (issue 19 item 2): while
// the seeds move little, as between the steps of an optimization, a diagram re-sorts the lists
// by the new positions instead of searching them anew, with the radius within which each list
// holds every seed shrunk by the moves; the diagram is the same either way. Empty until a
// diagram fills it; one per sequence of diagrams over the same seeds.
class NeighborCache {
 public:
  NeighborCache();
  ~NeighborCache();
  NeighborCache(const NeighborCache&) = delete;
  NeighborCache& operator=(const NeighborCache&) = delete;

 private:
  friend class RestrictedVoronoiDiagram;
  struct State;
  std::unique_ptr<State> state_;
};

// What one traversal leaves for the next over the same surface (issue 18, issue 19 item 4:
// topology control and polishing work locally): every triangle's polygons, the seeds they were
// cut for, and the seeds' neighbour lists. A traversal given it clips again only the triangles
// that a seed which moved, came or went may reach, and hands on the others' polygons as they
// were: the sinks get the same polygons, in the same order, as without it. Empty until a
// traversal fills it; one per surface.
class TraversalMemory {
 public:
  TraversalMemory();
  ~TraversalMemory();
  TraversalMemory(const TraversalMemory&) = delete;
  TraversalMemory& operator=(const TraversalMemory&) = delete;

 private:
  friend class RestrictedVoronoiDiagram;
  struct State;
  std::unique_ptr<State> state_;
};

class RestrictedVoronoiDiagram {
 public:
  // Builds a kd-tree over the seeds and each seed's list of nearest seeds. Throws
  // InvalidArgument for no seeds, a non-finite seed, or two identical seeds (naming both).
  // `surface` must outlive this object.
  RestrictedVoronoiDiagram(const TriangleMesh& surface, std::vector<Vec3> seeds);
  // The same, with the lists from `cache` where the seeds moved little since, and left there
  // for the next.
  RestrictedVoronoiDiagram(const TriangleMesh& surface, std::vector<Vec3> seeds,
                           NeighborCache& cache);
  // The same, with the lists that `memory` holds from its last diagram carried over for the
  // seeds that did not change since, and this diagram's left there; traverse with the same
  // memory.
  RestrictedVoronoiDiagram(const TriangleMesh& surface, std::vector<Vec3> seeds,
                           TraversalMemory& memory);
  ~RestrictedVoronoiDiagram();
  RestrictedVoronoiDiagram(RestrictedVoronoiDiagram&&) noexcept;
  RestrictedVoronoiDiagram& operator=(RestrictedVoronoiDiagram&&) noexcept;

  // Clips every triangle and hands each non-empty polygon to each sink, in one pass. Triangles
  // of zero area (exactly collinear corners) have no polygons.
  TraversalStats traverse(std::span<PolygonSink* const> sinks) const;
  TraversalStats traverse(PolygonSink& sink) const;
  // The same, replaying from `memory` the triangles no changed seed reaches, and leaving this
  // traversal's polygons there for the next.
  TraversalStats traverse(std::span<PolygonSink* const> sinks, TraversalMemory& memory) const;

  const TriangleMesh& surface() const;
  const std::vector<Vec3>& seeds() const;
  const RvdBuildTimes& build_times() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cvtmesh
