// Non-fatal facts about a mesh that a CLI user should hear about.
#pragma once

#include <string>

#include "cvtmesh/topology.hpp"

namespace cvtmesh::cli {

// Non-manifold edges and vertices, several components, non-orientable: one line each on
// stderr, prefixed by the file name.
void warn_about_topology(const std::string& file, const TopologyReport& t);

}  // namespace cvtmesh::cli
