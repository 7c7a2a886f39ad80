// Shared reporting of the CLI: the JSON keys every subcommand uses for a mesh, and the
// human-readable lines that go with them.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"

namespace cvtmesh::cli {

nlohmann::ordered_json mesh_json(const TopologyReport& topology, const QualityReport& quality);
// `distance` null: not measured (its keys are null).
void add_reference_json(nlohmann::ordered_json& json, const HausdorffReport* distance,
                        const TopologyReport& reference, bool same);

std::string topology_line(const TopologyReport& t);
std::string quality_lines(const QualityReport& q);
std::string hausdorff_lines(const HausdorffReport* h, const TopologyReport& self,
                            const TopologyReport& reference);

// The full report of a mesh: counts, topology and quality, plus, against a reference, the
// Hausdorff distance (when measured: `distance`, of `mesh` against `reference`) and the topology
// comparison.
// JSON and text carry the same figures.
struct MeshReport {
  TopologyReport topology;
  bool same_topology_as_reference = true;
  nlohmann::ordered_json json;
  std::string text;
};
// `reference_topology`: the reference's, when the caller has it already (else computed here).
MeshReport report_mesh(const std::string& name, const TriangleMesh& mesh,
                       const TriangleMesh* reference, const HausdorffReport* distance = nullptr,
                       const TopologyReport* reference_topology = nullptr);

// Non-fatal facts a user should hear about (non-manifold, several components, ...), one line
// each on stderr, prefixed by the file name.
void warn_about_topology(const std::string& file, const TopologyReport& t);

}  // namespace cvtmesh::cli
