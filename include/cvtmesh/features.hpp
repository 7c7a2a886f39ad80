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
  // The output's target edge length, or 0 to keep every curve. Curves made of sharp edges only
  // (no boundary, non-manifold or user edge) are dropped where they are not features at this
  // scale: when shorter than twice it (details below the output's resolution, noise on scans),
  // and, with `creases_at_scale`, when they do not fold by `angle_deg` between sides that are
  // flat within this distance (a jagged fold of a coarse organic model or a noisy scan, whose
  // tracing costs angles and topology; CAD creases have flat or gently curved sides), or when
  // the input around the curves they are connected to bends at its own resolution (the median
  // dihedral angle of the other edges there is over a tenth of `angle_deg` along most of them:
  // the folds of a low-poly organic model, flat-sided at a finer scale), or when free at both
  // ends (meeting no other feature) and shorter than 8 times it or than a third of the square
  // root of its component's area (a fold of an organic model's polygons; CAD creases end where
  // they meet other creases), or when one of its ends leaves along a boundary edge with a sector
  // of the surface under 30° between them, kNarrowAngleDeg (a wedge no triangle fills well; the
  // boundary stays), or when another curve joins the same two corners within half of it all
  // along (twins: one is kept, the shorter). With `creases_at_scale`, a sharp turn is a corner
  // only where both its curves are at least 0.3 times it long (the jagged rim of a scan's hole),
  // or where all the curves it is connected to are together shorter than twice it (a small
  // part's or hole's outline). remesh sets it to its target edge length.
  double scale = 0;
  bool creases_at_scale = true;  // all but the length rule; off when --feature-angle is given
  // More feature edges, chosen by the user: each must be an edge of the mesh.
  std::vector<Edge> user_edges;
  // More corners, chosen by the user (vertex ids): each becomes an output vertex at exactly its
  // position, on a curve or alone on the surface (remesh pins the pinch vertex where two parts
  // touch this way, so that the output touches there too).
  std::vector<Index> user_corners;
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

  bool empty() const { return edges.empty() && corners.empty(); }
};

// InvalidArgument when a user edge names a vertex out of range or is not an edge of the mesh, or a
// user corner is out of range.
Features detect_features(const TriangleMesh& mesh, const FeatureSettings& settings);

// The narrowest angle of the surface between two feature edges at a vertex (summed over the
// triangles between them, going round the vertex), in degrees; 360 when no vertex has two. An
// output that traces both curves has a triangle with at most about this angle there, so it
// bounds θmin: a sharp tip of a CAD part is as narrow in any faithful output.
double narrowest_feature_sector_deg(const TriangleMesh& mesh, const Features& features);

// An input vertex where two feature curves meet at a narrow angle: any faithful output has
// about that angle there (issue 18 item 6).
struct NarrowAngle {
  Vec3 at;
  double angle_deg;  // the narrowest sector of the surface between two feature edges there
};
// The vertices whose narrowest sector between two feature edges is under `below_deg`.
std::vector<NarrowAngle> narrow_feature_angles(const TriangleMesh& mesh, const Features& features,
                                               double below_deg);

// Reads a list of feature edges: one edge per line as two vertex ids (0-based, as in the mesh
// file's vertex order), blank lines and lines starting with '#' ignored. InputError, naming
// the file and line, for anything else.
std::vector<Edge> read_feature_edges(const std::filesystem::path& path);

}  // namespace cvtmesh
