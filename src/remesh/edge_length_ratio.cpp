#include "remesh/edge_length_ratio.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "features/edge_uses.hpp"

namespace cvtmesh {

std::vector<double> edge_length_ratios(const TriangleMesh& output,
                                       const SurfaceProjector& projector, const SizeField* field,
                                       double uniform) {
  std::vector<double> target(output.vertices.size(), uniform);
  if (field) {
    tbb::parallel_for(std::size_t{0}, target.size(), [&](std::size_t v) {
      const SurfaceProjector::Foot foot = projector.nearest(output.vertices[v]);
      target[v] = field->at(projector.surface_triangle(foot.triangle), foot.point);
    });
  }
  std::vector<double> ratio;
  for (const Edge& e : sorted_edges(output))
    ratio.push_back(distance(output.vertices[e[0]], output.vertices[e[1]]) /
                    ((target[e[0]] + target[e[1]]) / 2));
  return ratio;
}

EdgeLengthRatio ratio_percentiles(std::vector<double> ratio) {
  if (ratio.empty()) return {};
  std::sort(ratio.begin(), ratio.end());
  const auto percentile = [&](double p) {
    return ratio[static_cast<std::size_t>(std::lround(p * static_cast<double>(ratio.size() - 1)))];
  };
  return {percentile(0.05), percentile(0.5), percentile(0.95)};
}

}  // namespace cvtmesh
