// The restricted Delaunay triangulation from the RVD's symbols (paper §4.4): one triangle per
// RVD vertex of type C (dual_triangle).
#include "cvtmesh/repair.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "voronoi/dual_triangle.hpp"

namespace cvtmesh {

void RestrictedDelaunayBuilder::begin(std::size_t chunks) {
  chunks_.assign(chunks, {});
}

void RestrictedDelaunayBuilder::polygon(std::size_t chunk, const RvdPolygon& poly) {
  for (std::size_t k = 0; k < poly.vertices.size(); ++k)
    if (const auto t = dual_triangle(poly, k)) chunks_[chunk].push_back(*t);
}

void RestrictedDelaunayBuilder::end() {
  result_ = {};
  result_.vertices = rvd_.seeds();
  for (const auto& found : chunks_)
    result_.triangles.insert(result_.triangles.end(), found.begin(), found.end());
  chunks_.clear();
  // A Voronoi edge crossing the surface several times gives the same triangle several times.
  remove_duplicate_triangles(result_);
}

}  // namespace cvtmesh
