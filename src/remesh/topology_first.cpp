#include "remesh/topology_first.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>

#include "cvtmesh/topology.hpp"
#include "system/elapsed.hpp"

namespace cvtmesh {

namespace {

// Whether an output has its input's topology: the same components, Euler characteristics and
// boundary loops, and no defect the input did not have (a manifold input gives a manifold).
bool topology_kept(const RemeshResult& r) {
  const TopologyReport out = analyze_topology(r.mesh);
  const TopologyReport& in = r.input_topology;
  return r.triangles_removed == 0 && same_topology(out, in) &&
         (out.is_manifold() || !in.is_manifold());
}

}  // namespace

UnitRemesh remesh_unit_topology_first(const TriangleMesh& input, const RemeshSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  UnitRemesh first = remesh_unit(input, settings);
  const RemeshResult& r = first.result;
  if (settings.mode == CvtMode::rcvt || !settings.features.sharp_edges || r.time_limit_reached ||
      topology_kept(r))
    return first;
  RemeshSettings plain = settings;
  plain.features.sharp_edges = false;
  const Features kept = detect_features(input, plain.features);
  std::vector<Edge> dropped;
  std::set_difference(r.features.edges.begin(), r.features.edges.end(), kept.edges.begin(),
                      kept.edges.end(), std::back_inserter(dropped));
  if (dropped.empty()) return first;
  if (settings.time_limit > 0) {
    const double spent = seconds_since(start);
    if (spent >= settings.time_limit) return first;
    plain.time_limit = settings.time_limit - spent;
  }
  UnitRemesh second = remesh_unit(input, plain);
  RemeshResult& s = second.result;
  if (!topology_kept(s)) return first;
  s.feature_edges_dropped = std::move(dropped);
  s.iterations += r.iterations;
  s.rvd_evaluations += r.rvd_evaluations;
  s.seconds_initialization += r.seconds_initialization;
  s.seconds_rcvt += r.seconds_rcvt;
  s.seconds_ccvt += r.seconds_ccvt;
  s.seconds_extraction += r.seconds_extraction;
  return second;
}

}  // namespace cvtmesh
