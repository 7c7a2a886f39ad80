#include "remesh/topology_first.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <optional>
#include <tuple>
#include <utility>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/topology.hpp"
#include "features/feature_seeds.hpp"
#include "remesh/mend_topology.hpp"
#include "remesh/pipeline.hpp"
#include "system/elapsed.hpp"

namespace cvtmesh {

namespace {

// The gradation of the adaptive sizes that uniform ones give way to: the default of
// `--adaptive`.
constexpr double kFallbackGradation = 1.5;

// How many times the count may double for the topology: at most 4 times the count asked for,
// and more while it is under kSmallCount, where a remesh costs little (femur.off at 50: its two
// handles, 0.0003 across, lost at 100 and 200; kept at 400, adaptive).
constexpr int kCountDoublings = 2;
constexpr std::size_t kSmallCount = 1000;
// How many times the count may grow for features that need more seeds than it leaves.
constexpr int kFeatureGrowths = 3;

// How well an output keeps its input's topology: 2 when it has the same components, Euler
// characteristics and boundary loops, and no defect the input did not have (a manifold input
// gives a manifold) without the last step's help; 1 when the last step removed triangles and
// closing the holes gave the topology back; 0 when the topology differs.
int topology_kept(const RemeshResult& r) {
  if (!keeps_topology(analyze_topology(r.mesh), r.input_topology)) return 0;
  return r.triangles_removed == 0 ? 2 : 1;
}

// All of a remesh's time, its phases summed.
double seconds_of(const RemeshResult& r) {
  return r.seconds_initialization + r.seconds_rcvt + r.seconds_ccvt + r.seconds_extraction;
}

// `s` with the adaptive sizes that even ones give way to.
RemeshSettings with_adaptive_sizes(RemeshSettings s) {
  s.sizing.adaptive = kFallbackGradation;
  return s;
}

// remesh_unit again with `settings`, within what is left of their time limit after `start`;
// none if nothing is left, or if these settings cannot be met (a redo's features needing more
// vertices than its count, say): a second try never turns an output into an error. The
// progress callback is told first (`detail`: how this try differs; `tries`: the tries so far,
// counted up).
std::optional<UnitRemesh> retried(const TriangleMesh& input, RemeshSettings settings,
                                  std::chrono::steady_clock::time_point start, const char* detail,
                                  int& tries) {
  if (settings.time_limit > 0) {
    const double spent = seconds_since(start);
    if (spent >= settings.time_limit) return std::nullopt;
    settings.time_limit -= spent;
  }
  ++tries;
  if (settings.progress)
    settings.progress({"redo", tries, 0, 0, seconds_since(start), settings.vertices, 0, detail});
  try {
    return remesh_unit(input, settings);
  } catch (const InvalidArgument&) {
    return std::nullopt;
  }
}

// How well an output keeps its input's topology, for choosing between outputs: whether it does,
// one with triangles over one without, fewer triangles through others where the input has none
// (the output's own crossings: an invalid output, where holes the last step closed are valid),
// then topology_kept.
std::tuple<bool, bool, std::ptrdiff_t, int> rank(const RemeshResult& r) {
  const int kept = topology_kept(r);
  return {kept > 0, !r.mesh.triangles.empty(),
          -static_cast<std::ptrdiff_t>(r.output_crossing_triangles), kept};
}

// Keeps in `best` the one of `best` and a remesh `redo` of the same input that keeps the
// topology better (`best` on a tie); returns whether that is `redo`. Both runs' work is counted
// in the one kept: a redo not taken counts as topology control's and extraction's time, a redo
// taken has the time and the evaluations of the runs before it added to its own.
bool take_better(UnitRemesh& best, UnitRemesh redo) {
  RemeshResult& r = best.result;
  RemeshResult& s = redo.result;
  const double redone = seconds_of(s);
  if (rank(s) <= rank(r)) {
    r.seconds_topology += redone;
    r.seconds_extraction += redone;
    return false;
  }
  s.seconds_topology = r.seconds_topology + redone;
  s.iterations += r.iterations;
  s.rvd_evaluations += r.rvd_evaluations;
  s.seconds_initialization += r.seconds_initialization;
  s.seconds_rcvt += r.seconds_rcvt;
  s.seconds_ccvt += r.seconds_ccvt;
  s.seconds_extraction += r.seconds_extraction;
  best = std::move(redo);
  return true;
}

// The first remesh, with `settings` (updated to those used). Where the features need more seeds
// than the count leaves, which the count was checked against at even spacing (remesh/by_component)
// but sizes graded down to small holes put many more on their loops (the corpus's dragon with
// 1% of its triangles removed, 167 boundary loops, at 300: 533 feature seeds), the count grows to
// twice what they need, as it grows for the topology (issue 18 item 2), and the report says by how
// much. Not for the caller's own seeds or lengths without a count: the error stands.
UnitRemesh first_remesh(const TriangleMesh& input, RemeshSettings& settings) {
  try {
    return remesh_unit(input, settings);
  } catch (const FeaturesNeedMoreSeeds& e) {
    if (!settings.initial_seeds.empty() || lengths_as_given(settings)) throw;
    const std::size_t asked = unit_vertex_count(input, settings, nullptr);
    std::size_t needed = e.needed;
    for (int growth = 1;; ++growth) {
      const RemeshSettings more = at_count(settings, 2 * std::max(needed, asked));
      try {
        UnitRemesh grown = remesh_unit(input, more);
        grown.result.count_grown = more.vertices - asked;
        settings = more;
        return grown;
      } catch (const FeaturesNeedMoreSeeds& again) {
        if (growth == kFeatureGrowths) throw;
        needed = again.needed;
      }
    }
  }
}

}  // namespace

UnitRemesh remesh_unit_topology_first(const TriangleMesh& input, const RemeshSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  // The settings of the output kept so far.
  RemeshSettings used = settings;
  UnitRemesh best = first_remesh(input, used);
  int tries = 1;
  if (settings.mode == CvtMode::rcvt || best.result.time_limit_reached ||
      (topology_kept(best.result) == 2 && best.result.output_crossing_triangles == 0) ||
      crosses_itself_widely(best.result.input_crossing_triangles,
                            best.result.input_topology.triangles))
    return best;
  // First the sharp creases give way, if tracing them is what cost the topology, or made the
  // output pass through itself (spool.off at 200: its creases need more seeds than the count
  // leaves; traced, 7 crossing triangles, θmin 4.5°; without them none, 40.3°).
  if (used.features.sharp_edges) {
    RemeshSettings plain = used;
    plain.features.sharp_edges = false;
    const Features kept = detect_features(input, plain.features);
    std::vector<Edge> dropped;
    std::set_difference(best.result.features.edges.begin(), best.result.features.edges.end(),
                        kept.edges.begin(), kept.edges.end(), std::back_inserter(dropped));
    std::optional<UnitRemesh> second;
    if (!dropped.empty())
      second = retried(input, plain, start, "the sharp creases left out", tries);
    if (second) {
      second->result.feature_edges_dropped = std::move(dropped);
      if (take_better(best, std::move(*second))) used = plain;
    }
  }
  // Then even sizes, where the topology is still lost: parts thinner than the even edge
  // length, holes and gaps narrower than it, get cells their size from the start with the
  // local feature size (issue 20), where topology control's seeds come too late or too few
  // (tower_holes.obj at 1k: a 3-vertex hole 0.17 edge lengths across, 0.1 from a window).
  // Not for the caller's own sizes (nor the count's growth below) or seeds, not with topology
  // control off, not where the time is up, and not on an input with edges of three triangles or
  // more, whose junctions no count resolves (truck.obj of libigl's tutorial data, 50 parts with
  // 54 such edges, at 5k: 133 s with them, 43 s without, 30 s before either; 55, 55 and 56
  // parts out).
  if (topology_kept(best.result) > 0 || best.result.time_limit_reached ||
      !used.initial_seeds.empty() || used.topology_rounds == 0 ||
      best.result.input_topology.nonmanifold_edges > 0)
    return best;
  // A redo with `at` (`detail`: how it differs), kept if it keeps the topology better
  // (take_better), with the creases dropped so far; its report says whether it adapted the sizes
  // and by how many vertices the count grew.
  const auto redo = [&](const RemeshSettings& at, const char* detail, bool adapted,
                        std::size_t grown_by) {
    std::optional<UnitRemesh> next = retried(input, at, start, detail, tries);
    if (!next) return;
    next->result.count_grown = grown_by;
    next->result.sizes_adapted = adapted;
    next->result.feature_edges_dropped = best.result.feature_edges_dropped;
    take_better(best, std::move(*next));
  };
  if (!used.sizing.active()) redo(with_adaptive_sizes(used), "adaptive sizes", true, 0);
  // Last, the count grows, as the paper's rule lets it for the topology alone (§4.4, issue 18
  // item 2): where neither topology control's seeds nor the sizes kept it at the count asked
  // for (ADIS16480.STL of trimesh's test models, a CAD part of genus 24, at 1k; kept at 2k with
  // 2,608 seeds added), the count doubles, and again. Sizes scaled to a count (`--adaptive`, or
  // the caller's lengths with a count) grow with it (man.off with 1% of its triangles removed,
  // 329 boundary loops, adaptive at 4k: kept at 8k); the caller's lengths without a count are
  // the output's size, and stay.
  if (lengths_as_given(used)) return best;
  const std::size_t asked = unit_vertex_count(input, settings, nullptr);
  RemeshSettings more = at_count(used, unit_vertex_count(input, used, nullptr));
  const auto lost = [&] {
    return topology_kept(best.result) == 0 && !best.result.time_limit_reached;
  };
  // Even sizes that lose the topology at a grown count are tried adaptive at that count too:
  // what is left is narrower than the spacing, and the local feature size gives it many times
  // the seeds where doubling the count shortens every edge by √2 only (a femur with 61
  // one-triangle holes in its thin walls, at 1.5k: lost at 3k and 6k with even sizes, kept at 6k
  // adaptive; femur.off at 300, kept at 600 adaptive, 1,409 vertices, where even sizes kept it at
  // 1,200 with 2,407). After the even ones, not instead: adaptive sizes at 600 lost a femur with
  // 1% of its triangles removed, at 300, that even ones keep there. Not where the input crosses
  // itself (as topology control found): no sizes separate sheets that cross, and the tries only
  // cost (blade.off with noise folding its slivers through one another, at 1.5k: 6 tries in
  // 172 s, against 4 in 94 s without them, the same output).
  const bool even = !settings.sizing.active() && !used.sizing.active();
  const bool adapt_too = even && best.result.input_crossing_triangles == 0;
  for (int doubling = 0; (doubling < kCountDoublings || more.vertices < kSmallCount) && lost();
       ++doubling) {
    more.vertices *= 2;
    redo(more, even ? "even sizes" : "the same sizes", false, more.vertices - asked);
    if (adapt_too && lost())
      redo(with_adaptive_sizes(more), "adaptive sizes", true, more.vertices - asked);
  }
  return best;
}

}  // namespace cvtmesh
