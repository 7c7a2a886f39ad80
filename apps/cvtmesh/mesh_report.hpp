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
void add_reference_json(nlohmann::ordered_json& json, const HausdorffReport& distance,
                        const TopologyReport& reference, bool same);

std::string topology_line(const TopologyReport& t);
std::string quality_lines(const QualityReport& q);
std::string hausdorff_lines(const HausdorffReport& h, const TopologyReport& self,
                            const TopologyReport& reference);

// Non-fatal facts a user should hear about (non-manifold, several components, ...), one line
// each on stderr, prefixed by the file name.
void warn_about_topology(const std::string& file, const TopologyReport& t);

}  // namespace cvtmesh::cli
