// Sharp features and boundaries of an input surface (paper §4.3): feature edges, the curves
// they chain into, and the corners where curves end, meet or turn sharply.
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

using Edge = std::array<Index, 2>;  // two vertex ids, smaller first

struct FeatureSettings {
  // Detect sharp edges: an interior edge is sharp when the angle between its two triangles'
  // normals exceeds `angle_deg` (0° = flat). A curve vertex where the curve turns by more than
  // `angle_deg` is a corner too. Boundary edges and non-manifold edges are features always.
  bool sharp_edges = true;
  double angle_deg = 60;
  // Curves made of sharp edges only, shorter than this, are dropped: noise on scans, or details
  // below the output's resolution (remesh sets it to the target edge length). 0: keep all.
  double min_sharp_curve_length = 0;
  // More feature edges, chosen by the user: each must be an edge of the mesh.
  std::vector<Edge> user_edges;
};

// A chain of feature edges between two corners, or a closed loop without corners.
struct FeatureCurve {
  std::vector<Index> vertices;  // input vertex ids along the curve
  bool closed = false;          // a loop: the last vertex connects to the first (not repeated)
};

struct Features {
  std::vector<Edge> edges;     // sorted
  std::vector<Index> corners;  // sorted
  std::vector<FeatureCurve> curves;

  bool empty() const { return edges.empty(); }
};

// InvalidArgument when a user edge names a vertex out of range or is not an edge of the mesh.
Features detect_features(const TriangleMesh& mesh, const FeatureSettings& settings);

// The narrowest angle of the surface between two feature edges at a vertex (summed over the
// triangles between them, going round the vertex), in degrees; 360 when no vertex has two. An
// output that traces both curves has a triangle with at most about this angle there, so it
// bounds θmin: a sharp tip of a CAD part is as narrow in any faithful output.
double narrowest_feature_sector_deg(const TriangleMesh& mesh, const Features& features);

// Reads a list of feature edges: one edge per line as two vertex ids (0-based, as in the mesh
// file's vertex order), blank lines and lines starting with '#' ignored. InputError, naming
// the file and line, for anything else.
std::vector<Edge> read_feature_edges(const std::filesystem::path& path);

}  // namespace cvtmesh
