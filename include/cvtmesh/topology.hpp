// Combinatorial facts about a triangle mesh: components, boundaries, manifoldness, genus.
#pragma once

#include <cstddef>
#include <optional>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

struct TopologyReport {
  std::size_t vertices = 0;  // vertices used by at least one triangle
  std::size_t unreferenced_vertices = 0;
  std::size_t edges = 0;  // distinct undirected edges
  std::size_t triangles = 0;
  std::size_t components = 0;            // triangles connected through shared vertices
  std::size_t boundary_edges = 0;        // edges with exactly one triangle
  std::size_t boundary_loops = 0;        // connected components of the boundary-edge graph
  std::size_t nonmanifold_edges = 0;     // edges with three or more triangles
  std::size_t nonmanifold_vertices = 0;  // vertices whose incident triangles form >1 fan
  bool orientable = true;  // every component can be oriented consistently (manifold edges)
  bool consistently_oriented = true;   // every manifold interior edge is used once each way
  long long euler_characteristic = 0;  // V - E + F
  // Σ over components of (2 - χ_i - b_i)/2; only for edge- and vertex-manifold orientable meshes.
  std::optional<long long> genus;

  bool is_manifold() const { return nonmanifold_edges == 0 && nonmanifold_vertices == 0; }
  bool is_closed() const { return boundary_edges == 0; }
};

TopologyReport analyze_topology(const TriangleMesh& mesh);

// Same components, Euler characteristic and boundary loops.
bool same_topology(const TopologyReport& a, const TopologyReport& b);

// Whether an output (`out`) keeps its input's (`in`) topology as a remesh must: the same topology,
// and a manifold where the input is one.
bool keeps_topology(const TopologyReport& out, const TopologyReport& in);

}  // namespace cvtmesh
