#include "geometry/orient_triangles.hpp"

#include "geometry/triangle_sides.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

namespace cvtmesh {

namespace {

// A triangle across a manifold edge, and whether the two run along that edge the same way (one
// of them must then flip).
struct Across {
  std::size_t triangle;
  bool same_way;
};

// Calls visit(first side, second side) for each edge of exactly two triangles.
template <class Visit>
void for_manifold_edges(const std::vector<TriangleSide>& sides, const Visit& visit) {
  for_each_side_run(sides, [&](std::size_t i, std::size_t j) {
    if (j - i == 2) visit(sides[i], sides[i + 1]);
  });
}

double area(const TriangleMesh& mesh, std::size_t t) {
  const auto [a, b, c] = mesh.corners(t);
  return 0.5 * norm(cross(b - a, c - a));
}

}  // namespace

std::vector<std::size_t> triangles_to_flip(const TriangleMesh& mesh) {
  return triangles_to_flip(mesh, sorted_sides(mesh));
}

std::vector<std::size_t> triangles_to_flip(const TriangleMesh& mesh,
                                           const std::vector<TriangleSide>& sides) {
  const std::size_t nt = mesh.triangles.size();
  // Most meshes are consistent already: that is all there is to find out then.
  bool consistent = true;
  for_manifold_edges(sides, [&](const TriangleSide& a, const TriangleSide& b) {
    consistent = consistent && a.forward != b.forward;
  });
  if (consistent) return {};
  // Each triangle has a neighbour across each of its manifold edges, three at most.
  std::vector<std::array<Across, 3>> across(nt);
  std::vector<std::uint8_t> neighbours(nt, 0);
  for_manifold_edges(sides, [&](const TriangleSide& a, const TriangleSide& b) {
    const bool same_way = a.forward == b.forward;
    across[a.triangle][neighbours[a.triangle]++] = {b.triangle, same_way};
    across[b.triangle][neighbours[b.triangle]++] = {a.triangle, same_way};
  });
  std::vector<std::int8_t> flip(nt, -1);  // -1: not reached yet
  std::vector<std::size_t> flips, patch;
  for (std::size_t first = 0; first < nt; ++first) {
    if (flip[first] >= 0) continue;
    // Breadth first over the patch, each triangle flipped or not as the one it was reached from
    // requires.
    patch.assign(1, first);
    flip[first] = 0;
    bool orientable = true;
    for (std::size_t k = 0; k < patch.size(); ++k) {
      const std::size_t t = patch[k];
      for (std::uint8_t e = 0; e < neighbours[t]; ++e) {
        const auto [u, same_way] = across[t][e];
        const std::int8_t wanted = static_cast<std::int8_t>(flip[t] ^ (same_way ? 1 : 0));
        if (flip[u] < 0) {
          flip[u] = wanted;
          patch.push_back(u);
        } else if (flip[u] != wanted) {
          orientable = false;
        }
      }
    }
    if (!orientable) continue;
    double flipped_area = 0, kept_area = 0;
    for (const std::size_t t : patch) (flip[t] ? flipped_area : kept_area) += area(mesh, t);
    const std::int8_t flipped = flipped_area > kept_area ? 0 : 1;  // the minority flips
    for (const std::size_t t : patch)
      if (flip[t] == flipped) flips.push_back(t);
  }
  std::sort(flips.begin(), flips.end());
  return flips;
}

void flip_triangles(TriangleMesh& mesh, const std::vector<std::size_t>& triangles) {
  for (const std::size_t t : triangles) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
}

std::size_t orient_consistently(TriangleMesh& mesh) {
  const std::vector<std::size_t> flips = triangles_to_flip(mesh);
  flip_triangles(mesh, flips);
  return flips.size();
}

}  // namespace cvtmesh
