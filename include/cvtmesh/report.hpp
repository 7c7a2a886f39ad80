// The reports cvtmesh gives of a mesh and of a remesh, as JSON and as text with the same
// figures. The CLI prints them (`--json` or not); the Python module returns the JSON as a dict,
// so both speak with the same keys.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"

namespace cvtmesh {

nlohmann::ordered_json mesh_json(const TopologyReport& topology, const QualityReport& quality);
// `distance` null: not measured (its keys are null).
void add_reference_json(nlohmann::ordered_json& json, const HausdorffReport* distance,
                        const TopologyReport& reference, bool same);

std::string topology_line(const TopologyReport& t);
// One line (with its newline) for a remesh's progress callback, as the CLI prints it: an
// iteration's energy and gradient, a round of topology control's seeds, or a redo's reason.
std::string progress_line(const RemeshProgress& p);
std::string quality_lines(const QualityReport& q);
std::string hausdorff_lines(const HausdorffReport* h, const TopologyReport& self,
                            const TopologyReport& reference);

// The full report of a mesh: counts, topology and quality, plus, against a reference, the
// Hausdorff distance (when measured: `distance`, of `mesh` against `reference`), the topology
// comparison, and the quality away from the reference's narrow angles between features
// (`reference_features`, or those detect_features finds with its default settings). JSON and
// text carry the same figures.
struct MeshReport {
  TopologyReport topology;
  bool same_topology_as_reference = true;
  nlohmann::ordered_json json;
  std::string text;
};
// `reference_topology`: the reference's, when the caller has it already (else computed here).
MeshReport report_mesh(const std::string& name, const TriangleMesh& mesh,
                       const TriangleMesh* reference, const HausdorffReport* distance = nullptr,
                       const TopologyReport* reference_topology = nullptr,
                       const Features* reference_features = nullptr);

// Hausdorff samples per surface of a remesh's report (RemeshSettings::hausdorff), spread evenly,
// besides every vertex and edge midpoint of both meshes: the mean's sampling error is about 1%
// (eight.off at 1k vertices: 0.0598% against 0.0601% with 200k samples; over the 57 shared meshes
// at 1k, 0.8% from the dense figure on average, where 20k independent samples were 1.0%), and
// at 1k vertices the report costs a median 8% of the remesh (12% with 20k independent samples,
// 2 to 30 ms). `quality --ref` measures densely.
inline constexpr std::size_t kRemeshReportSamples = 8'000;

// The report of remesh(input) = result, named `name` (the output's): report_mesh of the output
// against the input, then the features kept (distance to the input's curves, corners), topology
// control, the CVT's figures and the phases' times; `filled`: what fill_holes did to the input
// before (`input` is then the filled one). `cvtmesh remesh` prints it.
MeshReport remesh_report(const std::string& name, const TriangleMesh& input,
                         const RemeshResult& result, const HoleFilling& filled = {});

}  // namespace cvtmesh
