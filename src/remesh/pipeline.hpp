// The remeshing pipeline (paper §4) on one surface of about unit size: remesh() scales the input
// and runs it on each connected component (remesh/by_component).
#pragma once

#include <cstddef>
#include <vector>

#include "cvtmesh/remesh.hpp"

namespace cvtmesh {

class SizeField;

// Throws InvalidArgument unless the settings give one output size at most, and none only for
// initial seeds (their count is the size) or target lengths given as they are.
void check_output_size(const RemeshSettings& s);

// The scale at which an adaptive sizing detects the features whose gaps narrow it (issue 20
// item 1), before the sizes and so the count are known: FeatureSettings::scale if set, else the
// even spacing of the count asked for, else the edge length asked for.
double scale_before_sizing(const TriangleMesh& mesh, const RemeshSettings& s);

// Whether the output's size is the caller's target lengths as they are: a sizing with no count
// and no edge length to scale it to (nothing then grows or shares out a count).
inline bool lengths_as_given(const RemeshSettings& s) {
  return s.sizing.active() && s.vertices == 0 && s.edge_length == 0 && s.edge_length_rel == 0;
}

// `s` with its size set by a vertex count alone.
inline RemeshSettings at_count(RemeshSettings s, std::size_t vertices) {
  s.vertices = vertices;
  s.edge_length = s.edge_length_rel = 0;
  return s;
}

// requested_vertex_count for a mesh of about unit size (see size_exponent in cvtmesh/mesh.hpp),
// with the size field of its sizing, if any.
std::size_t unit_vertex_count(const TriangleMesh& mesh, const RemeshSettings& s,
                              const SizeField* field);

struct UnitRemesh {
  RemeshResult result;
  std::vector<double> edge_ratios;  // per output edge: length / target (edge_length_ratios)
};

// The remesher proper, on a mesh of about unit size.
UnitRemesh remesh_unit(const TriangleMesh& input, const RemeshSettings& settings);

}  // namespace cvtmesh
