// The restricted Delaunay triangle dual to an RVD vertex (paper §4.4): a vertex of cell i lying
// on bisectors (i, a) and (i, b) is where the Voronoi edge of seeds i, a, b crosses the surface.
#pragma once

#include <algorithm>
#include <optional>

#include "cvtmesh/rvd.hpp"

namespace cvtmesh {

// Vertex k of `poly` as a triangle (seed, a, b), oriented like the input facet, rotated to start
// at its smallest seed; nullopt unless the vertex is of type C and `poly`'s seed is the smallest
// of the three (each triangle is met from each of its cells: this keeps one find).
inline std::optional<Triangle> dual_triangle(const RvdPolygon& poly, std::size_t k) {
  const auto& v = poly.vertices;
  const std::size_t n = v.size();
  if (v[k].bisector_count() != 2) return std::nullopt;
  // The bisector shared by consecutive vertices: the plane their side lies on.
  auto shared = [](const RvdVertex& x, const RvdVertex& y) {
    return (x.symbols[0] == y.symbols[0] || x.symbols[0] == y.symbols[1]) ? x.symbols[0]
                                                                          : x.symbols[1];
  };
  // The polygon turns counter-clockwise (input orientation) around cell i: at this vertex it
  // arrives along bisector a and leaves along bisector b, so around the vertex the cells come in
  // the order i, a, b, and (i, a, b) is oriented like the input facet.
  const auto a = static_cast<Index>(shared(v[(k + n - 1) % n], v[k]));
  const auto b = static_cast<Index>(shared(v[k], v[(k + 1) % n]));
  if (!(poly.seed < a && poly.seed < b)) return std::nullopt;
  return Triangle{poly.seed, a, b};
}

}  // namespace cvtmesh
