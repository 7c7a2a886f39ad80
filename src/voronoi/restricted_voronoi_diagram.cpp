// The RVD traversal (paper §3.1-3.3): first the cell of each input vertex, exactly; then per
// input triangle, whole if its corners share a cell, else a FIFO queue of cells starting from
// its first corner's; each cell clips the triangle by the bisectors within the security
// radius, and the seeds across the clipped polygon's edges join the queue.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>

#include "cvtmesh/rvd.hpp"
#include "geometry/median.hpp"
#include "geometry/point_tree.hpp"
#include "predicates/side_of_bisector.hpp"
#include "system/elapsed.hpp"
#include "voronoi/kept_chunks.hpp"
#include "voronoi/polygon_reach.hpp"
#include "voronoi/seed_neighbors.hpp"
#include "voronoi/traversal_record.hpp"

namespace cvtmesh {

namespace {

// Input vertices per chunk of the owner walks: fixed, so where walks start from the kd-tree
// does not depend on the thread count.
constexpr std::size_t kChunkSize = 1024;

// Polygons per chunk of the triangle traversal, about. A coarse input has many cells per
// triangle (3torus.off: 46 triangles under 5k seeds), so chunks of a fixed triangle count would
// leave it on one core. The chunking depends on the input and the seed count only; sinks add
// up chunk after chunk in traversal order, so no result depends on it anyway.
constexpr std::size_t kPolygonsPerChunk = 2048;

// Triangles per chunk, from the polygon count of a well-spread tessellation: each triangle, plus
// about 4 more per seed (a cell of about 6 sides spans several triangles' edges). Past 64, a
// multiple of 64, so that a few seeds more or less seldom change it: a traversal then takes over
// the chunks of its TraversalMemory's record that no changed seed reaches, instead of copying
// them. (A power of two would change it more seldom still, but chunks just past one, whose
// sinks' arrays then grow to twice what they hold, made igea's peak memory 6% higher.)
// And at least kMinChunks chunks where the triangles allow, a count that depends on the triangles
// alone: a small traversal (a small input, topology control's patches around its defects) then
// keeps every core busy, where a chunk or two held all its work.
constexpr std::size_t kMinChunks = 16;
std::size_t triangles_per_chunk(std::size_t triangles, std::size_t seeds) {
  constexpr std::size_t kStep = 64;
  const double polygons_per_triangle = 1 + 4 * static_cast<double>(seeds) / triangles;
  const auto size = static_cast<std::size_t>(kPolygonsPerChunk / polygons_per_triangle);
  const std::size_t by_polygons =
      size < kStep ? std::max<std::size_t>(1, size) : size / kStep * kStep;
  return std::min(by_polygons, std::max<std::size_t>(1, (triangles + kMinChunks - 1) / kMinChunks));
}

// Nearest seeds stored per seed: enough for nearly every polygon of a centroidal tessellation
// (about 6 Voronoi neighbours on a surface), few enough to find fast; the rest come from
// radius searches (see Impl::for_candidates). igea → 10k seeds: 12 makes a whole remesh 2-3%
// faster than 20 (fewer kNN results per seed and evaluation, few more radius searches).
constexpr std::size_t kStoredNeighbors = 12;
// A neighbour cache's lists are kept while the median of their complete radii is at least this
// fraction of a fresh search's: a step of an optimization moves seeds a fraction of their
// spacing.
constexpr double kKeptReach = 0.75;

using Polygon = std::vector<RvdVertex>;

// Per-thread scratch: polygon buffers, the cell queue, and a visit stamp per seed (the stamp of
// a seed equals the current triangle's when it was already queued for it).
struct Scratch {
  Polygon polygon, clipped;
  std::vector<char> inside;  // per polygon vertex: on the cell's side of the current bisector
  std::deque<Index> queue;
  std::vector<std::size_t> stamp;
  predicates::PredicateCounters counters;
  std::size_t polygons = 0, cells_clipped = 0, replayed = 0;
  // The current chunk's radius searches (Impl::for_candidates), per seed: the seeds within
  // `reach2` of it. A cell that spans several input triangles asks again on each, mostly within
  // the same reach (couplingdown.off at 1k, graded sizes: its 330,000 searches were 10% of the
  // remesh). Kept for a chunk only, so that they take little memory on large inputs.
  struct Searched {
    double reach2 = -1;
    std::vector<Index> found;
  };
  std::unordered_map<Index, Searched> searched;
  std::size_t radius_searches = 0;
};

// A version for a new traversal record (TraversalMemory::State::version): never 0, never one
// given before, in this process.
std::uint64_t next_record_version() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

}  // namespace

struct RestrictedVoronoiDiagram::Impl {
  const TriangleMesh* surface;
  std::vector<Vec3> seeds;
  // Shared with a TraversalMemory, if one was given, which keeps them for the next diagram.
  std::shared_ptr<const SeedNeighbors> neighbors;
  std::unique_ptr<PointTree> nearest;

  // Takes the seeds, builds the kd-tree and the lists (from `cache` if it has them for seeds
  // that moved little, or from `memory`'s for the seeds that did not change; then left there).
  void build(const TriangleMesh& on, std::vector<Vec3> points,
             std::unique_ptr<NeighborCache::State>* cache,
             std::unique_ptr<TraversalMemory::State>* memory = nullptr);

  // Zero-area triangles (exact test) have no facet plane, and nothing to clip.
  bool flat(std::size_t t) const {
    const auto [a, b, c] = surface->corners(t);
    using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
    return CGAL::collinear(Point(a.x, a.y, a.z), Point(b.x, b.y, b.z), Point(c.x, c.y, c.z));
  }
  RvdBuildTimes times;

  // Every triangle's polygons to the sinks: clipped, or, where `old` holds them still, replayed;
  // and to `recorder`, if given, which takes over the chunks of `old` that stay as they were.
  // `version`: where `old` is a memory's record, its version (see TraversalMemory::State), set
  // to the new record's; the sinks that keep chunks and served `old` get none of those chunks.
  TraversalStats traverse(std::span<PolygonSink* const> sinks, TraversalRecord* old,
                          PolygonRecorder* recorder, std::uint64_t* version = nullptr) const;

  // Clips `polygon` (in the frame's cell) by the bisector with seed j. Returns whether the
  // bisector cut it, i.e. some vertex lies on j's side.
  bool clip(const predicates::ClipFrame& frame, Index j, Scratch& s) const {
    const Polygon& in = s.polygon;
    const std::size_t n = in.size();
    s.inside.resize(n);
    bool all_inside = true;
    for (std::size_t k = 0; k < n; ++k) {
      s.inside[k] = predicates::closer_to_cell(frame, in[k], j, s.counters);
      all_inside &= s.inside[k] != 0;
    }
    if (all_inside) return false;
    Polygon& out = s.clipped;
    out.clear();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t next = (k + 1) % n;
      if (s.inside[k]) out.push_back(in[k]);
      if (s.inside[k] != s.inside[next])
        out.push_back(predicates::bisector_crossing(frame, in[k], in[next], j));
    }
    std::swap(s.polygon, s.clipped);
    return true;
  }

  // A seed near q, usually the nearest: a greedy walk in floating point over the stored nearest
  // seeds, from `from`. Consecutive vertices are usually close, so the walk is short; owner_of
  // then decides exactly.
  Index walk_to_nearest(const Vec3& q, Index from) const {
    const auto d2 = [&](Index s) { return dot(seeds[s] - q, seeds[s] - q); };
    for (double best = d2(from);;) {
      const Index at = from;
      for (Index j : neighbors->of(at)) {
        const double d = d2(j);
        if (d < best) best = d, from = j;
      }
      if (from == at) return from;
    }
  }

  // Calls visit(j, J, |J|²), J = x_j − x_i, for every seed j whose bisector with seed i may meet
  // a polygon around x_i, until visit returns false. reach2() is the polygon's current squared
  // reach from x_i, rounded up: a bisector farther than twice that cannot cut the polygon. The
  // stored nearest seeds come first, nearest first, so the loop can stop at the first one out of
  // reach; if the polygon still reaches past them all, a radius search fetches the rest (rare
  // once seeds are well spread). The clipped polygon does not depend on the order of the
  // bisectors. J and |J|² go to visit as the reach test made them (BisectorScreen takes them).
  template <class Reach2, class Visit>
  void for_candidates(Index i, Scratch& s, const Reach2& reach2, const Visit& visit) const {
    const Vec3& xi = seeds[i];
    // Whether j is within reach, and if so whether visit(j) says go on: `stop` set otherwise.
    const auto reached = [&](Index j, bool& stop) {
      const Vec3 J = seeds[j] - xi;
      const double JJ = dot(J, J);
      if (!(JJ * (1 - 1e-10) <= 4 * reach2())) return false;
      stop = !visit(j, J, JJ);
      return true;
    };
    const std::span<const Index> stored = neighbors->of(i);
    bool stop = false;
    for (Index j : stored) {
      if (!reached(j, stop)) break;
      if (stop) return;
    }
    // Done if the list holds every seed within reach, else a radius search finds the rest.
    const double search2 = 4 * reach2() * (1 + 1e-6);
    if (search2 < neighbors->complete2[i]) return;
    Scratch::Searched& searched = s.searched[i];
    if (searched.reach2 < search2) {
      ++s.radius_searches;
      nearest->within(seeds[i], search2, searched.found);
      searched.reach2 = search2;
    }
    // In the search's own order (deterministic; clipping's result does not depend on it, nor on
    // seeds beyond the reach an earlier, wider search brought), skipping the seeds the shrinking
    // polygon no longer reaches.
    for (Index j : searched.found)
      if (j != i && std::find(stored.begin(), stored.end(), j) == stored.end() &&
          reached(j, stop) && stop)
        return;
  }

  // The cell that contains input vertex q, decided exactly (with the perturbation's tie rule):
  // from a seed near q, move to any candidate the exact predicate finds closer until none is.
  // Each move strictly lowers q's perturbed power distance, so the walk ends; and any seed
  // closer to q than x_i lies within 2|q − x_i| of x_i, where the candidates reach, so it ends
  // in q's cell.
  Index owner_of(const Vec3& q, Index start, Scratch& s) const {
    predicates::ClipFrame frame{{q, q, q}, seeds.data(), walk_to_nearest(q, start)};
    const RvdVertex corner = predicates::corner_vertex(frame, 0);
    for (;;) {
      const Index i = frame.cell;
      const double reach2 = squared_reach(seeds[i], std::span(&corner, 1));
      for_candidates(
          i, s, [&] { return reach2; },
          [&](Index j, const Vec3&, double) {
            if (predicates::closer_to_cell(frame, corner, j, s.counters)) return true;
            frame.cell = j;
            return false;
          });
      if (frame.cell == i) return i;
    }
  }

  // Whether a ball around the polygon (bounding_ball) lies on x_i's side of bisector (i, j) with
  // a margin far beyond rounding: then every polygon vertex in it does, and clipping by j would
  // change nothing. A cheap test that spares the exact predicates most neighbours. Over the ball
  // (centre x_i + C, radius r), 2 J·(p − x_i) is at most 2 J·C + 2 |J| r, and the bisector is at
  // J·J (J = x_j − x_i); with a slack of 1e-10 (J·J + 2 |J| (|C| + r)), the test
  // |J| k < A, k = 2r (1 + 1e-10) + 2e-10 |C|, A = (1 − 1e-10) J·J − 2 J·C, is squared: no square
  // root per neighbour (BM_CvtPass 2-5% faster, the same polygons). Squares that may have lost
  // their precision to underflow (far below unit size) answer no: the exact clip decides (a k²
  // that may have is taken as infinite, which no A² passes).
  class BisectorScreen {
   public:
    BisectorScreen(const Ball& ball, const Vec3& xi) : C_(ball.center - xi) {
      const double k = 2 * ball.radius * (1 + 1e-10) + 2e-10 * norm(C_);
      k2_ = k * k;
      if (k2_ != 0 && k2_ < kNormal) k2_ = std::numeric_limits<double>::infinity();
    }
    // J = x_j − x_i, JJ = |J|².
    bool beyond(const Vec3& J, double JJ) const {
      const double A = JJ * (1 - 1e-10) - 2 * dot(J, C_);
      const double AA = A * A;
      return A > 0 && AA >= kNormal && JJ * k2_ < AA;
    }

   private:
    static constexpr double kNormal = 0x1p-900;  // far above 2^-1022, where doubles lose digits
    Vec3 C_;
    double k2_;
  };

  // `owners`: the cell of each input vertex (owner_of).
  void clip_triangle(std::size_t t, std::size_t chunk, std::span<PolygonSink* const> sinks,
                     const std::vector<Index>& owners, Scratch& s) const {
    predicates::ClipFrame frame{surface->corners(t), seeds.data(), 0};
    const auto& corners = surface->triangles[t];
    const Index start = owners[corners[0]];
    if (owners[corners[1]] == start && owners[corners[2]] == start) {
      // Cells are convex: a triangle whose corners lie in one cell lies in it whole.
      frame.cell = start;
      ++s.cells_clipped;
      s.polygon.clear();
      for (int k = 0; k < 3; ++k) s.polygon.push_back(predicates::corner_vertex(frame, k));
      ++s.polygons;
      const RvdPolygon polygon{start, static_cast<Index>(t), s.polygon};
      for (PolygonSink* sink : sinks) sink->polygon(chunk, polygon);
      return;
    }
    const std::size_t stamp = t + 1;
    s.stamp[start] = stamp;
    s.queue.assign(1, start);
    while (!s.queue.empty()) {
      const Index i = s.queue.front();
      s.queue.pop_front();
      frame.cell = i;
      ++s.cells_clipped;
      s.polygon.clear();
      for (int k = 0; k < 3; ++k) s.polygon.push_back(predicates::corner_vertex(frame, k));
      double reach2 = squared_reach(seeds[i], s.polygon);
      BisectorScreen screen(bounding_ball(s.polygon), seeds[i]);
      for_candidates(
          i, s, [&] { return reach2; },
          [&](Index j, const Vec3& J, double JJ) {
            if (screen.beyond(J, JJ) || !clip(frame, j, s)) return true;
            if (s.polygon.empty()) return false;
            reach2 = squared_reach(seeds[i], s.polygon);
            screen = BisectorScreen(bounding_ball(s.polygon), seeds[i]);
            return true;
          });
      if (s.polygon.size() < 3) continue;
      // From its least vertex by symbols: the same polygon, and the same sums over it, whatever
      // order the bisectors cut in (it differs with the candidate lists, see NeighborCache).
      std::rotate(s.polygon.begin(),
                  std::min_element(
                      s.polygon.begin(), s.polygon.end(),
                      [](const RvdVertex& a, const RvdVertex& b) { return a.symbols < b.symbols; }),
                  s.polygon.end());
      // Only the seeds across the final polygon's edges have cells on this triangle: every
      // bisector symbol of a vertex names the seed across one of its two edges. (A seed whose
      // bisector cut an earlier, larger polygon may own nothing here; queueing it would clip
      // the whole triangle again, and on a coarse input that is thousands of cells wide.) Queued
      // from the rotated polygon, so that the cells come in the same order whatever the lists.
      for (const RvdVertex& v : s.polygon)
        for (const std::int32_t j : v.symbols)
          if (j >= 0 && s.stamp[static_cast<Index>(j)] != stamp) {
            s.stamp[static_cast<Index>(j)] = stamp;
            s.queue.push_back(static_cast<Index>(j));
          }
      ++s.polygons;
      const RvdPolygon polygon{i, static_cast<Index>(t), s.polygon};
      for (PolygonSink* sink : sinks) sink->polygon(chunk, polygon);
    }
  }
};

struct NeighborCache::State {
  SeedNeighbors lists;
  std::vector<Vec3> at;     // the seeds the lists are for
  double fresh_median = 0;  // of the complete radii (squared) when last searched
};

NeighborCache::NeighborCache() = default;
NeighborCache::~NeighborCache() = default;

RestrictedVoronoiDiagram::RestrictedVoronoiDiagram(const TriangleMesh& surface,
                                                   std::vector<Vec3> seeds)
    : impl_(std::make_unique<Impl>()) {
  impl_->build(surface, std::move(seeds), nullptr);
}

RestrictedVoronoiDiagram::RestrictedVoronoiDiagram(const TriangleMesh& surface,
                                                   std::vector<Vec3> seeds, NeighborCache& cache)
    : impl_(std::make_unique<Impl>()) {
  impl_->build(surface, std::move(seeds), &cache.state_);
}

RestrictedVoronoiDiagram::RestrictedVoronoiDiagram(const TriangleMesh& surface,
                                                   std::vector<Vec3> seeds, TraversalMemory& memory)
    : impl_(std::make_unique<Impl>()) {
  impl_->build(surface, std::move(seeds), nullptr, &memory.state_);
}

void RestrictedVoronoiDiagram::Impl::build(const TriangleMesh& on, std::vector<Vec3> points,
                                           std::unique_ptr<NeighborCache::State>* cache,
                                           std::unique_ptr<TraversalMemory::State>* memory) {
  surface = &on;
  seeds = std::move(points);
  reject_non_finite_seeds(seeds);
  NeighborCache::State* state = cache ? cache->get() : nullptr;
  const bool cached = state && state->at.size() == seeds.size();
  // nanoflann builds its tree on one thread: what needs no tree runs beside it (whole remeshes
  // on two cores 2-5% faster at 5k-10k vertices, outputs byte-identical).
  std::optional<MovedLists> shrunk;
  tbb::parallel_invoke(
      [&] {
        const auto start = std::chrono::steady_clock::now();
        nearest = std::make_unique<PointTree>(seeds);
        times.kdtree_seconds = seconds_since(start);
      },
      [&] {
        reject_identical_seeds(seeds);
        // Taken out of the cache, which gets this build's lists at its end (and stays empty,
        // so unused, if the build throws first).
        if (cached)
          shrunk = shrunk_for_moves(std::exchange(state->lists, {}), std::exchange(state->at, {}),
                                    seeds);
      });
  const auto start = std::chrono::steady_clock::now();
  // Kept while most lists still reach kKeptReach of what a search gives; past that, radius
  // searches would cost more than the search. The movers only shrink the radii further, so
  // lists that fail before them fail after.
  const auto reaching = [&](const SeedNeighbors& lists) {
    return median_of(lists.complete2) >= kKeptReach * kKeptReach * state->fresh_median;
  };
  // Lists that no longer reach far enough still bound how far a fresh search must look.
  std::optional<SeedNeighbors> earlier;
  if (shrunk && reaching(shrunk->lists)) {
    SeedNeighbors moved = bound_by_movers(std::move(*shrunk), seeds, *nearest);
    if (reaching(moved)) {
      neighbors = std::make_shared<const SeedNeighbors>(std::move(moved));
      times.neighbors_reused = true;
    } else {
      earlier = std::move(moved);
    }
  } else if (shrunk) {
    earlier = std::move(shrunk->lists);
  }
  if (memory) {
    if (!*memory) *memory = std::make_unique<TraversalMemory::State>();
    TraversalMemory::State& m = **memory;
    neighbors = std::make_shared<const SeedNeighbors>(
        m.lists ? carried_over(*m.lists, m.lists_at, seeds, *nearest, kStoredNeighbors)
                : nearest_neighbors(seeds, *nearest, kStoredNeighbors));
    times.neighbors_reused = m.lists != nullptr;
    m.lists = neighbors;
    m.lists_at = seeds;
  } else if (!times.neighbors_reused) {
    neighbors = std::make_shared<const SeedNeighbors>(
        nearest_neighbors(seeds, *nearest, kStoredNeighbors, earlier ? &*earlier : nullptr));
    if (cache) {
      if (!state) state = (*cache = std::make_unique<NeighborCache::State>()).get();
      state->fresh_median = median_of(neighbors->complete2);
    }
  }
  if (state) {
    state->lists = *neighbors;
    state->at = seeds;
  }
  times.neighbors_seconds = seconds_since(start);
}

RestrictedVoronoiDiagram::~RestrictedVoronoiDiagram() = default;
RestrictedVoronoiDiagram::RestrictedVoronoiDiagram(RestrictedVoronoiDiagram&&) noexcept = default;
RestrictedVoronoiDiagram& RestrictedVoronoiDiagram::operator=(RestrictedVoronoiDiagram&&) noexcept =
    default;

const TriangleMesh& RestrictedVoronoiDiagram::surface() const {
  return *impl_->surface;
}
const std::vector<Vec3>& RestrictedVoronoiDiagram::seeds() const {
  return impl_->seeds;
}
const RvdBuildTimes& RestrictedVoronoiDiagram::build_times() const {
  return impl_->times;
}

TraversalStats RestrictedVoronoiDiagram::traverse(PolygonSink& sink) const {
  PolygonSink* sinks[] = {&sink};
  return traverse(sinks);
}

TraversalStats RestrictedVoronoiDiagram::traverse(std::span<PolygonSink* const> sinks) const {
  return impl_->traverse(sinks, nullptr, nullptr);
}

TraversalStats RestrictedVoronoiDiagram::traverse(std::span<PolygonSink* const> sinks,
                                                  TraversalMemory& memory) const {
  const TriangleMesh& surface = *impl_->surface;
  if (!memory.state_) memory.state_ = std::make_unique<TraversalMemory::State>();
  // Taken out: a traversal that does not run to its end leaves the memory without a record.
  TraversalRecord old = std::exchange(memory.state_->record, {});
  std::uint64_t version = std::exchange(memory.state_->version, 0);
  PolygonRecorder recorder(surface, impl_->seeds,
                           triangles_per_chunk(surface.triangles.size(), impl_->seeds.size()));
  const TraversalStats stats =
      impl_->traverse(sinks, old.covers(surface) ? &old : nullptr, &recorder, &version);
  memory.state_->record = std::move(recorder).take();
  memory.state_->version = version;
  return stats;
}

TraversalStats RestrictedVoronoiDiagram::Impl::traverse(std::span<PolygonSink* const> sinks,
                                                        TraversalRecord* old,
                                                        PolygonRecorder* recorder,
                                                        std::uint64_t* version) const {
  const std::size_t triangles = surface->triangles.size();
  const std::size_t chunk_size = triangles_per_chunk(triangles, seeds.size());
  const std::size_t chunks = (triangles + chunk_size - 1) / chunk_size;
  // The triangles to clip: all of them, or those whose polygons `old` does not hold still.
  const std::vector<char> stale = old ? old->stale_triangles(seeds) : std::vector<char>{};
  const auto clipped = [&](std::size_t t) { return !old || stale[t]; };
  // Chunked alike, each chunk of `old` serves the same chunk here only: one that is as it was
  // goes to the recorder whole, the others are freed once done (the others' polygons go to the
  // recorder one by one), so that the two records are not held whole at once.
  const bool adoptable = old && recorder && old->chunk_size() == chunk_size;
  std::vector<char> kept(chunks, 0);
  if (adoptable)
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
      const auto begin = stale.begin() + static_cast<std::ptrdiff_t>(c * chunk_size);
      const auto end =
          stale.begin() + static_cast<std::ptrdiff_t>(std::min(triangles, (c + 1) * chunk_size));
      kept[c] = std::none_of(begin, end, [](char x) { return x != 0; });
    });
  // The sinks that keep their chunks from `old` (PolygonSink::keeps_chunks); the others get
  // those chunks' polygons replayed. A traversal that changes no chunk keeps the version.
  const bool same = adoptable && all_kept(kept);
  const std::uint64_t served = version ? *version : 0;
  if (version && !same) *version = next_record_version();
  std::vector<PolygonSink*> replayed;
  for (PolygonSink* sink : sinks) {
    if (adoptable && served != 0 && sink->keeps_chunks() && sink->served_ == served)
      sink->begin_kept(chunks, kept);
    else {
      sink->begin(chunks);
      replayed.push_back(sink);
    }
  }
  std::vector<PolygonSink*> recorded(sinks.begin(), sinks.end());
  if (recorder) recorded.push_back(recorder);
  if (recorder) recorder->begin(chunks);
  tbb::enumerable_thread_specific<Scratch> scratch([&] {
    Scratch s;
    s.stamp.assign(seeds.size(), 0);
    return s;
  });
  // The cells of the clipped triangles' corners. Walks start from the previous such vertex's
  // cell (vertices in a file are mostly in spatial order), or from the kd-tree at each chunk's
  // first: alike on any thread count.
  const std::vector<Vec3>& vertices = surface->vertices;
  std::vector<char> needed(vertices.size(), old ? 0 : 1);
  if (old)
    for (std::size_t t = 0; t < triangles; ++t)
      if (stale[t])
        for (const Index v : surface->triangles[t]) needed[v] = 1;
  std::vector<Index> owners(vertices.size(), kNoIndex);
  tbb::parallel_for(std::size_t{0}, (vertices.size() + kChunkSize - 1) / kChunkSize,
                    [&](std::size_t chunk) {
                      Scratch& s = scratch.local();
                      s.searched.clear();
                      const std::size_t begin = chunk * kChunkSize;
                      const std::size_t end = std::min(vertices.size(), begin + kChunkSize);
                      Index last = kNoIndex;
                      for (std::size_t v = begin; v < end; ++v) {
                        if (!needed[v]) continue;
                        const Index from = last == kNoIndex ? (*nearest)(vertices[v]) : last;
                        last = owners[v] = owner_of(vertices[v], from, s);
                      }
                    });
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t chunk) {
    Scratch& s = scratch.local();
    s.searched.clear();  // a chunk's triangles are near one another, the searches they share too
    const std::size_t begin = chunk * chunk_size, end = std::min(triangles, begin + chunk_size);
    const bool whole = kept[chunk] != 0;
    for (std::size_t t = begin; t < end; ++t) {
      if (!clipped(t)) {
        // A chunk kept whole goes only to the sinks that do not keep it.
        s.polygons += whole && replayed.empty()
                          ? old->polygon_count(t)
                          : old->replay(t, chunk, whole ? replayed : recorded, s.clipped);
        ++s.replayed;
      } else if (!flat(t)) {
        clip_triangle(t, chunk, recorded, owners, s);
      }
    }
    if (whole)
      recorder->adopt(chunk, *old);
    else if (recorder)
      recorder->finish(chunk);
    if (adoptable && !whole) old->release(chunk);
    for (PolygonSink* sink : whole ? std::span<PolygonSink* const>(replayed) : sinks)
      sink->chunk_done(chunk);
  });
  for (PolygonSink* sink : recorded) sink->end();
  // Without a memory, what a sink now holds is of no record.
  for (PolygonSink* sink : sinks)
    if (sink->keeps_chunks()) sink->served_ = version ? *version : 0;
  TraversalStats stats;
  for (const Scratch& s : scratch) {
    stats.polygons += s.polygons;
    stats.cells_clipped += s.cells_clipped;
    stats.predicates += s.counters.predicates;
    stats.exact_fallbacks += s.counters.exact_fallbacks;
    stats.perturbed_ties += s.counters.perturbed_ties;
    stats.radius_searches += s.radius_searches;
    stats.triangles_replayed += s.replayed;
  }
  return stats;
}

}  // namespace cvtmesh
