#include "features/renumber_features.hpp"

#include <algorithm>

namespace cvtmesh {

Features renumbered(const Features& features, const std::vector<Index>& new_id) {
  Features out;
  out.edges.reserve(features.edges.size());
  for (const Edge& e : features.edges) {
    const Index a = new_id[e[0]], b = new_id[e[1]];
    out.edges.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(out.edges.begin(), out.edges.end());
  for (const Index c : features.corners) out.corners.push_back(new_id[c]);
  std::sort(out.corners.begin(), out.corners.end());
  out.curves = features.curves;
  for (FeatureCurve& curve : out.curves)
    for (Index& v : curve.vertices) v = new_id[v];
  return out;
}

}  // namespace cvtmesh
