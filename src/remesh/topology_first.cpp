#include "remesh/topology_first.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>

#include "cvtmesh/topology.hpp"
#include "system/elapsed.hpp"

namespace cvtmesh {

namespace {

// How well an output keeps its input's topology: 2 when it has the same components, Euler
// characteristics and boundary loops, and no defect the input did not have (a manifold input
// gives a manifold) without the last step's help; 1 when the last step removed triangles and
// closing the holes gave the topology back; 0 when the topology differs.
int topology_kept(const RemeshResult& r) {
  const TopologyReport out = analyze_topology(r.mesh);
  const TopologyReport& in = r.input_topology;
  if (!same_topology(out, in) || (!out.is_manifold() && in.is_manifold())) return 0;
  return r.triangles_removed == 0 ? 2 : 1;
}

}  // namespace

UnitRemesh remesh_unit_topology_first(const TriangleMesh& input, const RemeshSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  UnitRemesh first = remesh_unit(input, settings);
  const RemeshResult& r = first.result;
  if (settings.mode == CvtMode::rcvt || !settings.features.sharp_edges || r.time_limit_reached ||
      topology_kept(r) == 2)
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
  // The redone remesh is all topology control's, on top of the first's own.
  const double redone =
      s.seconds_initialization + s.seconds_rcvt + s.seconds_ccvt + s.seconds_extraction;
  if (topology_kept(s) <= topology_kept(r)) {
    first.result.seconds_topology += redone;
    first.result.seconds_extraction += redone;
    return first;
  }
  s.feature_edges_dropped = std::move(dropped);
  s.seconds_topology = r.seconds_topology + redone;
  s.iterations += r.iterations;
  s.rvd_evaluations += r.rvd_evaluations;
  s.seconds_initialization += r.seconds_initialization;
  s.seconds_rcvt += r.seconds_rcvt;
  s.seconds_ccvt += r.seconds_ccvt;
  s.seconds_extraction += r.seconds_extraction;
  return second;
}

}  // namespace cvtmesh
