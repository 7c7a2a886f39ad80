// The restricted Delaunay triangulation from the RVD's symbols (paper §4.4): an RVD vertex of
// cell i lying on bisectors (i, a) and (i, b) is where the dual Voronoi edge of seeds i, a, b
// crosses the surface, and so gives the triangle (i, a, b).
#include <algorithm>

#include "cvtmesh/repair.hpp"
#include "cvtmesh/rvd_consumers.hpp"

namespace cvtmesh {

namespace {

// The bisector shared by consecutive polygon vertices u and v: the plane their edge lies on.
std::int32_t shared_symbol(const RvdVertex& u, const RvdVertex& v) {
  return (u.symbols[0] == v.symbols[0] || u.symbols[0] == v.symbols[1]) ? u.symbols[0]
                                                                        : u.symbols[1];
}

Triangle rotated_to_smallest(Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

}  // namespace

void RestrictedDelaunayBuilder::begin(std::size_t chunks) {
  chunks_.assign(chunks, {});
}

void RestrictedDelaunayBuilder::polygon(std::size_t chunk, const RvdPolygon& poly) {
  const auto& v = poly.vertices;
  const std::size_t n = v.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (v[k].bisector_count() != 2) continue;
    // The polygon turns counter-clockwise (input orientation) around cell i: at this vertex it
    // arrives along bisector a and leaves along bisector b, so around the vertex the cells come
    // in the order i, a, b, and (i, a, b) is oriented like the input facet.
    const auto a = static_cast<Index>(shared_symbol(v[(k + n - 1) % n], v[k]));
    const auto b = static_cast<Index>(shared_symbol(v[k], v[(k + 1) % n]));
    // Each triangle is found from each of its three cells: keep the find from the smallest.
    if (poly.seed < a && poly.seed < b) chunks_[chunk].push_back({poly.seed, a, b});
  }
}

void RestrictedDelaunayBuilder::end() {
  result_ = {};
  result_.vertices = rvd_.seeds();
  for (const auto& found : chunks_)
    for (const Triangle& t : found) result_.triangles.push_back(rotated_to_smallest(t));
  chunks_.clear();
  // A Voronoi edge crossing the surface several times gives the same triangle several times.
  remove_duplicate_triangles(result_);
}

}  // namespace cvtmesh
